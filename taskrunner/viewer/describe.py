"""What the browser view reads, as JSON-ready data: a cell, a compiled tree, a replay.

A cell is described by its merged URDF (every robot prefixed and placed under ``world``,
as the planner sees it), whose mesh file names are rewritten to URLs
``meshes/<root>/<file>``: ``<root>`` names a folder holding a mesh of a loaded robot
(:class:`MeshRoots`), so the page never sees a server path and the server serves files
only from those folders (:meth:`MeshRoots.file`).
"""

from __future__ import annotations

import hashlib
import math
import xml.etree.ElementTree as ET
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath
from typing import Any
from urllib.parse import quote

import pinocchio as pin
import py_trees
from py_trees.behaviour import Behaviour

from taskrunner.robot.cell import Cell
from taskrunner.runtime.records import RunRecord
from taskrunner.runtime.replay import replay_of, scene_data
from taskrunner.scene import scene_from_cell

__all__ = ["MESH_TYPES", "MeshRoots", "describe_cell", "describe_replay", "describe_tree"]

# Files the mesh route serves (meshes, and what a DAE or OBJ may reference).
MESH_TYPES = {".stl": "model/stl", ".dae": "model/vnd.collada+xml", ".obj": "model/obj",
              ".mtl": "text/plain", ".png": "image/png", ".jpg": "image/jpeg",
              ".jpeg": "image/jpeg"}


def _root_id(folder: Path) -> str:
    return hashlib.sha256(str(folder).encode()).hexdigest()[:16]


@dataclass
class MeshRoots:
    """The folders mesh files may be served from, by id (the mesh folders of the robots
    in ``cells``)."""

    folders: dict[str, Path] = field(default_factory=dict)

    @classmethod
    def of_cells(cls, cells: Iterable[Cell]) -> MeshRoots:
        roots = cls()
        for cell in cells:
            for mesh in _mesh_elements(ET.fromstring(cell.model.urdf_xml)):
                roots.add(Path(mesh.get("filename", "")).parent)
        return roots

    def add(self, folder: Path) -> str:
        folder = folder.resolve()
        key = _root_id(folder)
        self.folders[key] = folder
        return key

    def file(self, root: str, relative: str) -> Path | None:
        """The file ``relative`` inside folder ``root``, or None: an unknown root, a path
        that leaves the folder (``..``, absolute, a symlink pointing out), a folder, or
        a file that is not a mesh or texture."""
        folder = self.folders.get(root)
        if folder is None or not relative or "\\" in relative or "\x00" in relative:
            return None
        parts = PurePosixPath(relative).parts
        if PurePosixPath(relative).is_absolute() or any(p in ("..", ".") for p in parts):
            return None
        try:
            path = (folder / relative).resolve(strict=True)
        except (OSError, RuntimeError):
            return None
        if not path.is_relative_to(folder) or not path.is_file():
            return None
        if path.suffix.lower() not in MESH_TYPES:
            return None
        return path


def _mesh_elements(urdf: ET.Element) -> list[ET.Element]:
    return [m for link in urdf.iter("link") for kind in ("visual",)
            for v in link.findall(kind) for m in v.findall("geometry/mesh")]


def _quat(rotation: Any) -> list[float]:
    q = pin.Quaternion(rotation)
    return [round(float(v), 6) for v in (q.x, q.y, q.z, q.w)]


def _finite(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def describe_cell(cell: Cell, cell_id: str, roots: MeshRoots) -> dict[str, Any]:
    """A cell for the page: ``urdf`` (merged, collision elements dropped, meshes as
    URLs), ``robots`` (name, prefix, base pose), ``joints`` (limits: rad, rad/s, rad/s²;
    null when unbounded), ``groups`` (joints, tip link, named poses with their values),
    ``start`` (joint values) and ``objects`` (the cell's fixed objects)."""
    model = cell.model
    urdf = ET.fromstring(model.urdf_xml)
    for link in urdf.iter("link"):
        for collision in link.findall("collision"):
            link.remove(collision)
    for mesh in _mesh_elements(urdf):
        path = Path(mesh.get("filename", ""))
        key = roots.add(path.parent)
        mesh.set("filename", f"meshes/{key}/{quote(path.name)}")
    start = cell.start_state()
    return {
        "id": cell_id,
        "name": cell.name,
        "description": cell.description,
        "urdf": ET.tostring(urdf, encoding="unicode"),
        "robots": [{"name": i.name, "prefix": i.prefix, "robot": i.source.parent.name,
                    "base": {"xyz": [round(float(v), 6) for v in i.base.translation],
                             "quat": _quat(i.base.rotation)}}
                   for i in model.instances],
        "joints": [{"name": j.name, "type": j.type, "robot": j.robot,
                    "lower": _finite(j.lower), "upper": _finite(j.upper),
                    "velocity": _finite(j.max_velocity),
                    "acceleration": _finite(j.max_acceleration),
                    "mimic": j.mimic is not None, "passive": j.passive}
                   for j in model.joints],
        "groups": [{"name": g.name, "joints": list(g.joint_names), "tip_link": g.tip_link,
                    "poses": {p: model.named_state(g.name, p).as_dict()
                              for p in model.named_state_names(g.name)}}
                   for g in model.groups.values()],
        "start": {n: round(float(v), 6) for n, v in zip(model.joint_names, start)},
        "objects": scene_data(scene_from_cell(cell).snapshot())["objects"],
    }


_KINDS = {py_trees.composites.Sequence: "sequence", py_trees.composites.Selector: "fallback",
          py_trees.composites.Parallel: "parallel"}


def describe_tree(root: Behaviour) -> dict[str, Any]:
    """A compiled tree: each node's ``name``, ``kind`` (sequence, fallback, parallel,
    decorator, or the leaf's class), ``location`` (task file:line; a composite's is its
    first child's), ``status`` and ``children``."""
    children = [describe_tree(c) for c in root.children]
    kind = next((k for cls, k in _KINDS.items() if isinstance(root, cls)), None)
    if kind is None:
        kind = "decorator" if isinstance(root, py_trees.decorators.Decorator) \
            else type(root).__name__
    location = getattr(root, "location", None)
    if location is None and children:
        location = children[0]["location"]
    return {"name": root.name, "kind": kind, "location": location,
            "status": root.status.value, "children": children}


def describe_replay(record: RunRecord) -> dict[str, Any]:
    """A record for the page's replay: the run's summary, its ``motions`` in order (node,
    file:line, time of the event, trajectory, the scene it started in, ``executed``: s
    of trajectory run; ``physics``: what a physics backend measured during it, or None),
    ``first_scene`` and ``final_scene``."""
    replay = replay_of(record)
    # A physics backend's measured joints and objects of each motion (its step's
    # ``physics`` event, after the motion's): the replay shows them instead of the plan.
    measured: dict[int, dict[str, Any]] = {}
    for event in record.events:
        if event.kind == "physics":
            earlier = [k for k, m in enumerate(replay.motions)
                       if m.seq < event.seq and m.node == event.node and k not in measured]
            if earlier:
                measured[earlier[-1]] = event.data
    return {
        "run_id": record.run_id, "task": record.task, "cell": record.cell,
        "status": record.status, "error": record.error, "backend": record.backend,
        "motions": [{"seq": m.seq, "node": m.node, "location": m.location, "time": m.time,
                     "trajectory": m.trajectory, "scene": m.scene, "executed": m.executed,
                     "physics": measured.get(k)}
                    for k, m in enumerate(replay.motions)],
        "first_scene": replay.first_scene,
        "final_scene": replay.final_scene,
    }
