"""The ROS 2 messages a run is exported as, their definitions and their CDR encoders.

Definitions are those of ROS 2 Humble (the same layout in Iron and Jazzy), written in
the ``ros2msg`` form that MCAP files and Foxglove's WebSocket protocol carry (rosbag2's
``docs/message_definition_encoding.md``): the top-level ``.msg`` text first, then each
type it uses, after a line of 80 ``=`` and a ``MSG: package/msg/Type`` line. Field order
and types are those of the ``.msg`` files of ``common_interfaces`` and
``rcl_interfaces`` (Apache-2.0); the tests check them against another library's copy of
ROS 2 Humble's types.

Times are integer nanoseconds since the UNIX epoch; lengths in m, angles in rad,
quaternions ``(x, y, z, w)``.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from taskrunner.export.cdr import CdrWriter

__all__ = ["DISPLAY_TRAJECTORY", "JOINT_STATE", "LOG", "MARKER_ARRAY", "STRING", "TF_MESSAGE",
           "LogLine", "Marker", "MessageType", "Transform", "encode_display_trajectory",
           "encode_joint_state", "encode_log", "encode_marker_array", "encode_string", "encode_tf_message"]

# One .msg text per type, as in its package (comments dropped).
_MSG = {
    "builtin_interfaces/msg/Time": "int32 sec\nuint32 nanosec\n",
    "builtin_interfaces/msg/Duration": "int32 sec\nuint32 nanosec\n",
    "std_msgs/msg/Header": "builtin_interfaces/Time stamp\nstring frame_id\n",
    "std_msgs/msg/String": "string data\n",
    "std_msgs/msg/ColorRGBA": "float32 r\nfloat32 g\nfloat32 b\nfloat32 a\n",
    "geometry_msgs/msg/Vector3": "float64 x\nfloat64 y\nfloat64 z\n",
    "geometry_msgs/msg/Point": "float64 x\nfloat64 y\nfloat64 z\n",
    "geometry_msgs/msg/Quaternion": "float64 x\nfloat64 y\nfloat64 z\nfloat64 w\n",
    "geometry_msgs/msg/Pose": "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n",
    "geometry_msgs/msg/Transform":
        "geometry_msgs/Vector3 translation\ngeometry_msgs/Quaternion rotation\n",
    "geometry_msgs/msg/TransformStamped":
        "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/Transform transform\n",
    "tf2_msgs/msg/TFMessage": "geometry_msgs/TransformStamped[] transforms\n",
    "sensor_msgs/msg/JointState":
        "std_msgs/Header header\nstring[] name\nfloat64[] position\nfloat64[] velocity\n"
        "float64[] effort\n",
    "sensor_msgs/msg/CompressedImage": "std_msgs/Header header\nstring format\nuint8[] data\n",
    "visualization_msgs/msg/UVCoordinate": "float32 u\nfloat32 v\n",
    "visualization_msgs/msg/MeshFile": "string filename\nuint8[] data\n",
    "visualization_msgs/msg/Marker":
        "int32 ARROW=0\nint32 CUBE=1\nint32 SPHERE=2\nint32 CYLINDER=3\nint32 LINE_STRIP=4\n"
        "int32 LINE_LIST=5\nint32 CUBE_LIST=6\nint32 SPHERE_LIST=7\nint32 POINTS=8\n"
        "int32 TEXT_VIEW_FACING=9\nint32 MESH_RESOURCE=10\nint32 TRIANGLE_LIST=11\n"
        "int32 ADD=0\nint32 MODIFY=0\nint32 DELETE=2\nint32 DELETEALL=3\n"
        "std_msgs/Header header\nstring ns\nint32 id\nint32 type\nint32 action\n"
        "geometry_msgs/Pose pose\ngeometry_msgs/Vector3 scale\nstd_msgs/ColorRGBA color\n"
        "builtin_interfaces/Duration lifetime\nbool frame_locked\n"
        "geometry_msgs/Point[] points\nstd_msgs/ColorRGBA[] colors\n"
        "string texture_resource\nsensor_msgs/CompressedImage texture\n"
        "visualization_msgs/UVCoordinate[] uv_coordinates\nstring text\n"
        "string mesh_resource\nvisualization_msgs/MeshFile mesh_file\n"
        "bool mesh_use_embedded_materials\n",
    "visualization_msgs/msg/MarkerArray": "visualization_msgs/Marker[] markers\n",
    "rcl_interfaces/msg/Log":
        "byte DEBUG=10\nbyte INFO=20\nbyte WARN=30\nbyte ERROR=40\nbyte FATAL=50\n"
        "builtin_interfaces/Time stamp\nuint8 level\nstring name\nstring msg\nstring file\n"
        "string function\nuint32 line\n",
    # moveit_msgs (BSD-3-Clause), its humble branch; same-package types without a
    # package, as in the .msg files.
    "geometry_msgs/msg/Twist": "Vector3 linear\nVector3 angular\n",
    "geometry_msgs/msg/Wrench": "Vector3 force\nVector3 torque\n",
    "sensor_msgs/msg/MultiDOFJointState":
        "std_msgs/Header header\nstring[] joint_names\ngeometry_msgs/Transform[] transforms\n"
        "geometry_msgs/Twist[] twist\ngeometry_msgs/Wrench[] wrench\n",
    "trajectory_msgs/msg/JointTrajectoryPoint":
        "float64[] positions\nfloat64[] velocities\nfloat64[] accelerations\nfloat64[] effort\n"
        "builtin_interfaces/Duration time_from_start\n",
    "trajectory_msgs/msg/JointTrajectory":
        "std_msgs/Header header\nstring[] joint_names\nJointTrajectoryPoint[] points\n",
    "trajectory_msgs/msg/MultiDOFJointTrajectoryPoint":
        "geometry_msgs/Transform[] transforms\ngeometry_msgs/Twist[] velocities\n"
        "geometry_msgs/Twist[] accelerations\nbuiltin_interfaces/Duration time_from_start\n",
    "trajectory_msgs/msg/MultiDOFJointTrajectory":
        "std_msgs/Header header\nstring[] joint_names\nMultiDOFJointTrajectoryPoint[] points\n",
    "shape_msgs/msg/SolidPrimitive":
        "uint8 BOX=1\nuint8 SPHERE=2\nuint8 CYLINDER=3\nuint8 CONE=4\nuint8 PRISM=5\n"
        "uint8 type\nfloat64[<=3] dimensions\nuint8 BOX_X=0\nuint8 BOX_Y=1\nuint8 BOX_Z=2\n"
        "uint8 SPHERE_RADIUS=0\nuint8 CYLINDER_HEIGHT=0\nuint8 CYLINDER_RADIUS=1\n"
        "uint8 CONE_HEIGHT=0\nuint8 CONE_RADIUS=1\nuint8 PRISM_HEIGHT=0\n"
        "geometry_msgs/Polygon polygon\n",
    "geometry_msgs/msg/Polygon": "Point32[] points\n",
    "geometry_msgs/msg/Point32": "float32 x\nfloat32 y\nfloat32 z\n",
    "shape_msgs/msg/MeshTriangle": "uint32[3] vertex_indices\n",
    "shape_msgs/msg/Mesh": "MeshTriangle[] triangles\ngeometry_msgs/Point[] vertices\n",
    "shape_msgs/msg/Plane": "float64[4] coef\n",
    "object_recognition_msgs/msg/ObjectType": "string key\nstring db\n",
    "moveit_msgs/msg/CollisionObject":
        "std_msgs/Header header\ngeometry_msgs/Pose pose\nstring id\n"
        "object_recognition_msgs/ObjectType type\nshape_msgs/SolidPrimitive[] primitives\n"
        "geometry_msgs/Pose[] primitive_poses\nshape_msgs/Mesh[] meshes\n"
        "geometry_msgs/Pose[] mesh_poses\nshape_msgs/Plane[] planes\n"
        "geometry_msgs/Pose[] plane_poses\nstring[] subframe_names\n"
        "geometry_msgs/Pose[] subframe_poses\nbyte ADD=0\nbyte REMOVE=1\nbyte APPEND=2\n"
        "byte MOVE=3\nbyte operation\n",
    "moveit_msgs/msg/AttachedCollisionObject":
        "string link_name\nCollisionObject object\nstring[] touch_links\n"
        "trajectory_msgs/JointTrajectory detach_posture\nfloat64 weight\n",
    "moveit_msgs/msg/RobotState":
        "sensor_msgs/JointState joint_state\n"
        "sensor_msgs/MultiDOFJointState multi_dof_joint_state\n"
        "AttachedCollisionObject[] attached_collision_objects\nbool is_diff\n",
    "moveit_msgs/msg/RobotTrajectory":
        "trajectory_msgs/JointTrajectory joint_trajectory\n"
        "trajectory_msgs/MultiDOFJointTrajectory multi_dof_joint_trajectory\n",
    "moveit_msgs/msg/DisplayTrajectory":
        "string model_id\nRobotTrajectory[] trajectory\nRobotState trajectory_start\n",
}

_PRIMITIVES = {"bool", "byte", "char", "float32", "float64", "int8", "uint8", "int16",
               "uint16", "int32", "uint32", "int64", "uint64", "string", "wstring"}


def _dependencies(name: str) -> list[str]:
    """The types ``name``'s fields use, recursively, each once, in order of first use."""
    out: list[str] = []

    def visit(type_name: str) -> None:
        for line in _MSG[type_name].splitlines():
            word = line.split()[0].split("[")[0]
            if "=" in line or word in _PRIMITIVES:
                continue
            package, _, short = word.rpartition("/")
            full = f"{package or type_name.split('/')[0]}/msg/{short}"
            if full not in out:
                out.append(full)
                visit(full)

    visit(name)
    return out


def _definition(name: str) -> str:
    parts = [_MSG[name]]
    for dependency in _dependencies(name):
        parts.append(f"{'=' * 80}\nMSG: {dependency}\n{_MSG[dependency]}")
    return "".join(parts)


@dataclass(frozen=True)
class MessageType:
    """A ROS 2 message type: ``name`` (``package/msg/Type``) and its complete
    ``ros2msg`` definition."""

    name: str
    definition: str


JOINT_STATE = MessageType("sensor_msgs/msg/JointState", _definition("sensor_msgs/msg/JointState"))
TF_MESSAGE = MessageType("tf2_msgs/msg/TFMessage", _definition("tf2_msgs/msg/TFMessage"))
STRING = MessageType("std_msgs/msg/String", _definition("std_msgs/msg/String"))
MARKER_ARRAY = MessageType("visualization_msgs/msg/MarkerArray",
                           _definition("visualization_msgs/msg/MarkerArray"))
LOG = MessageType("rcl_interfaces/msg/Log", _definition("rcl_interfaces/msg/Log"))
DISPLAY_TRAJECTORY = MessageType("moveit_msgs/msg/DisplayTrajectory",
                                 _definition("moveit_msgs/msg/DisplayTrajectory"))


def _time(w: CdrWriter, stamp_ns: int) -> None:
    sec, nanosec = divmod(int(stamp_ns), 1_000_000_000)
    w.int32(sec)
    w.uint32(nanosec)


def _header(w: CdrWriter, stamp_ns: int, frame_id: str) -> None:
    _time(w, stamp_ns)
    w.string(frame_id)


def _xyz(w: CdrWriter, xyz: Sequence[float]) -> None:
    for v in xyz:
        w.float64(float(v))


def _quat(w: CdrWriter, quat: Sequence[float]) -> None:
    for v in quat:
        w.float64(float(v))


def encode_joint_state(stamp_ns: int, names: Sequence[str], positions: Sequence[float] | np.ndarray,
                       velocities: Sequence[float] | np.ndarray = (),
                       efforts: Sequence[float] | np.ndarray = ()) -> bytes:
    """A ``sensor_msgs/JointState`` (rad or m, rad/s or m/s; empty: not known)."""
    w = CdrWriter()
    _header(w, stamp_ns, "")
    w.strings(names)
    w.float64s(positions)
    w.float64s(velocities)
    w.float64s(efforts)
    return w.getvalue()


@dataclass(frozen=True)
class Transform:
    """``parent_T_child`` at ``stamp_ns``: translation (m), rotation quaternion (x, y, z, w)."""

    stamp_ns: int
    parent: str
    child: str
    xyz: tuple[float, float, float]
    quat: tuple[float, float, float, float]


def encode_tf_message(transforms: Sequence[Transform]) -> bytes:
    """A ``tf2_msgs/TFMessage`` of ``geometry_msgs/TransformStamped``s."""
    w = CdrWriter()
    w.uint32(len(transforms))
    for t in transforms:
        _header(w, t.stamp_ns, t.parent)
        w.string(t.child)
        _xyz(w, t.xyz)
        _quat(w, t.quat)
    return w.getvalue()


def encode_string(text: str) -> bytes:
    """A ``std_msgs/String``."""
    w = CdrWriter()
    w.string(text)
    return w.getvalue()


# visualization_msgs/Marker's type and action constants.
CUBE, SPHERE, CYLINDER, MESH_RESOURCE = 1, 2, 3, 10
ADD, DELETEALL = 0, 3


@dataclass(frozen=True)
class Marker:
    """One ``visualization_msgs/Marker`` of a kind we draw (a shape, or DELETEALL).

    ``scale``: a box's size, a sphere's or cylinder's diameters and height (m), a mesh's
    scale factors. ``color``: r, g, b, a in 0..1.
    """

    stamp_ns: int
    frame_id: str
    ns: str
    id: int
    type: int = CUBE
    action: int = ADD
    xyz: tuple[float, float, float] = (0.0, 0.0, 0.0)
    quat: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)
    scale: tuple[float, float, float] = (1.0, 1.0, 1.0)
    color: tuple[float, float, float, float] = (0.6, 0.6, 0.6, 1.0)
    frame_locked: bool = False
    text: str = ""
    mesh_resource: str = ""
    points: tuple[tuple[float, float, float], ...] = field(default=())


def _marker(w: CdrWriter, m: Marker) -> None:
    _header(w, m.stamp_ns, m.frame_id)
    w.string(m.ns)
    w.int32(m.id)
    w.int32(m.type)
    w.int32(m.action)
    _xyz(w, m.xyz)            # pose.position
    _quat(w, m.quat)          # pose.orientation
    _xyz(w, m.scale)
    for v in m.color:
        w.float32(float(v))
    w.int32(0)                # lifetime: 0, forever
    w.uint32(0)
    w.bool(m.frame_locked)
    w.uint32(len(m.points))
    for point in m.points:
        _xyz(w, point)
    w.uint32(0)               # colors
    w.string("")              # texture_resource
    _header(w, 0, "")         # texture: an empty CompressedImage
    w.string("")
    w.uint8s(b"")
    w.uint32(0)               # uv_coordinates
    w.string(m.text)
    w.string(m.mesh_resource)
    w.string("")              # mesh_file: none
    w.uint8s(b"")
    w.bool(bool(m.mesh_resource))  # mesh_use_embedded_materials


def encode_marker_array(markers: Sequence[Marker]) -> bytes:
    """A ``visualization_msgs/MarkerArray``."""
    w = CdrWriter()
    w.uint32(len(markers))
    for marker in markers:
        _marker(w, marker)
    return w.getvalue()


# rcl_interfaces/Log's levels.
DEBUG, INFO, WARN, ERROR, FATAL = 10, 20, 30, 40, 50


@dataclass(frozen=True)
class LogLine:
    """One ``rcl_interfaces/Log`` (what ``/rosout`` carries): ``name`` is the logger's
    (the tree node's), ``file`` and ``line`` where in the task file it comes from."""

    stamp_ns: int
    level: int
    name: str
    msg: str
    file: str = ""
    function: str = ""
    line: int = 0


def encode_log(log: LogLine) -> bytes:
    """An ``rcl_interfaces/Log``."""
    w = CdrWriter()
    _time(w, log.stamp_ns)
    w.uint8(log.level)
    w.string(log.name)
    w.string(log.msg)
    w.string(log.file)
    w.string(log.function)
    w.uint32(log.line)
    return w.getvalue()


def _duration(w: CdrWriter, seconds: float) -> None:
    sec, nanosec = divmod(int(round(seconds * 1e9)), 1_000_000_000)
    w.int32(sec)
    w.uint32(nanosec)


def encode_display_trajectory(stamp_ns: int, model_id: str, joints: Sequence[str],
                              times: np.ndarray, positions: np.ndarray,
                              velocities: np.ndarray, accelerations: np.ndarray,
                              start_names: Sequence[str], start: np.ndarray) -> bytes:
    """A ``moveit_msgs/DisplayTrajectory`` of one joint trajectory (``times`` s from its
    start; one row of ``positions`` (rad or m), ``velocities`` and ``accelerations``
    per time, columns ``joints``), starting from the joint state ``start``
    (``start_names``). No multi-DOF joints; no attached objects (see the caller)."""
    w = CdrWriter()
    w.string(model_id)
    w.uint32(1)                          # trajectory: one RobotTrajectory
    _header(w, stamp_ns, "")             # joint_trajectory.header
    w.strings(joints)
    w.uint32(len(times))
    for k, t in enumerate(times):
        w.float64s(positions[k])
        w.float64s(velocities[k])
        w.float64s(accelerations[k])
        w.float64s(())                   # effort
        _duration(w, float(t))
    _header(w, stamp_ns, "")             # multi_dof_joint_trajectory: empty
    w.strings(())
    w.uint32(0)
    _header(w, stamp_ns, "")             # trajectory_start.joint_state
    w.strings(start_names)
    w.float64s(start)
    w.float64s(())
    w.float64s(())
    _header(w, stamp_ns, "")             # trajectory_start.multi_dof_joint_state: empty
    w.strings(())
    w.uint32(0)
    w.uint32(0)
    w.uint32(0)
    w.uint32(0)                          # attached_collision_objects
    w.bool(False)                        # is_diff
    return w.getvalue()
