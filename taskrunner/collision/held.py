"""Held objects in space-time: where each object an arm holds, takes or sets down during
the lanes' motions is, stretch by stretch of the common clock
(:mod:`taskrunner.collision.spacetime`).

A motion says what its arm holds while it runs (:attr:`TimedMotion.held`: the objects
attached to a link of its lane, each posed in that link's frame): a pick attaches between
two motions, a place releases. An object some motion holds (a *named* object) is, at each
instant:

- *held* by the lane whose motion holding it runs then (one of that lane's bodies,
  moving with its link); an arm at rest after its last motion also holds what the
  scene it is verified in has attached to its links (it has just taken it: its next
  motion is not on the schedule yet);
- else *in the world*, one of the bodies of the lane that last held it, where that lane
  set it down: its link's world pose at the end of the last motion holding it (the full
  state then) times its pose in that link's frame; before anything held it, where the
  first motion to hold it takes it (its link's world pose at that motion's start, times
  its pose there): an object picked up inside a ``parallel`` lies at its old place until
  the pick's motion takes it, and one set down lies where it was set from then on.

Between two motions of one lane, the arm at rest, an object in its hand and one it has
just set down or is about to take are in one place: the same body either way.

An object lying in the world is not to be touched by another lane's links (no
clearance, as a plan keeps off the world's objects), and its distances are not the
lanes' clearance; held ones keep the clearance. An object another lane holds may touch
it: a place may set one on it (a stack), as that lane's own plan has it.

A named object held, or lying, as the scene verified has it over the whole window is
*steady* (:attr:`HeldObjects.steady`, :attr:`HeldObjects.resting`): its pairs are walked
once over the window in that scene, with every pair of no named object. The common
clock is cut where another one (it *changes*) starts or stops being held; each stretch
gets a scene holding the named objects as they are then (:class:`Stretch`), and the
pairs of the changing ones are walked stretch by stretch in it: the scene verified where
it has them so; where the only difference is that objects lie where their lane, resting,
holds them in it (just taken, or about to be set down), that scene with the lane's joints
kept there; else a copy of it with the robot and the named objects only, with the
allowances of the scene verified that name them. The copies are kept per robot model and
thread by what they hold, so that the verifications of one schedule, which mostly see
the same stretches again, build each once.
"""

from __future__ import annotations

import threading
import weakref
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np
import pinocchio as pin

from taskrunner.collision.samples import state_columns
from taskrunner.types import Pose

if TYPE_CHECKING:  # the planning scene is above the collision core: passed in, not imported
    from taskrunner.collision.spacetime import Lane, TimedMotion
    from taskrunner.robot import RobotModel
    from taskrunner.scene import Scene, SceneObject

__all__ = ["HeldObjects", "Stretch", "held_objects", "lanes_state"]


@dataclass(frozen=True)
class Stretch:
    """A stretch of the common clock (``start`` to ``end``, s) over which what is held
    and where the named objects lie stay the same.

    Attributes:
        scene: the robot and the named objects as they are then (held: attached to their
            links; set down or not taken yet: in the world), kept: read, never edited.
        lanes: the lane (index) of each named object in the world then.
        frozen: state columns and their values: ``scene`` is the scene verified, in
            which the objects lying then are attached as their lane held them; with its
            joints there (the lane resting where it set them down or takes them), they
            lie where they do (only their pairs are walked: that lane's other bodies are
            not). None: ``scene`` holds them as they are.
    """

    start: float
    end: float
    scene: Scene
    lanes: Mapping[str, int]
    frozen: tuple[np.ndarray, np.ndarray] | None = None


@dataclass(frozen=True)
class HeldObjects:
    """The named objects (module text) and the stretches, in time order.

    Attributes:
        steady: the named objects held in the scene verified as they are held over the
            whole window; ``resting``: those lying in it as they lie over the whole
            window, with their lanes. The stretches are those where the others change.
    """

    named: frozenset[str]
    steady: frozenset[str]
    resting: Mapping[str, int]
    stretches: tuple[Stretch, ...]

    @property
    def changing(self) -> frozenset[str]:
        """The named objects neither steady nor resting."""
        return self.named - self.steady - frozenset(self.resting)


@dataclass(frozen=True)
class _Hold:
    """An object held by lane ``lane`` from ``start`` to ``end`` (s); ``taken`` and
    ``released``: the motion of the lane and its row (sample) where the lane is as it
    takes it and as it lets it go (None: not known; the lanes' state then)."""

    lane: int
    start: float
    end: float
    obj: SceneObject
    taken: tuple[TimedMotion, int] | None
    released: tuple[TimedMotion, int] | None


# An object lying where its lane leaves it: that lane, the state columns of the joints
# moving its link and their values there, the object as its lane held it.
_Freeze = tuple[int, np.ndarray, np.ndarray, "SceneObject"]

# Per thread, per robot geometry (one per robot model: kept while it lives): the scenes of
# the stretches, by what they hold, the latest few (a checker is one thread's at a time).
_LOCAL = threading.local()
_KEPT = 24
_KEPT_POSES = 64
_KEPT_OWNERS = 8
_INSTANT = 1e-9  # s
_SAME = 1e-7  # m, and in quaternion components: where an object set down lies, to rounding


def held_objects(scene: Scene, lanes: Sequence[Lane], times: tuple[float, float],
                 joint_lanes: tuple[np.ndarray, np.ndarray],
                 state_at: Callable[[float], np.ndarray]) -> HeldObjects | None:
    """The named objects of ``lanes`` and the stretches of ``times`` (s, the window
    verified) with their scenes (module text); None where no object is named.

    Args:
        joint_lanes: per pinocchio joint, the lane that moves it, and the lane that
            carries it (-1: none), as the verifier takes a body's lane.
        state_at: the full state at a time of the common clock (the lanes' motions).
    """
    if len(lanes) < 2 or not any(m.held for lane in lanes for m in lane.motions):
        return None
    pin_model = scene.robot.model
    moved_at, carried_at = joint_lanes
    # The lanes of links, kept per lanes' joints (the lane verified alternates between
    # the arms: the latest few).
    kept_owners: dict[int, tuple[np.ndarray, pin.Model, dict[str, int]]] | None = \
        getattr(_LOCAL, "owners", None)
    if kept_owners is None:
        kept_owners = _LOCAL.owners = {}
    last = kept_owners.get(id(moved_at))
    if last is None or last[0] is not moved_at or last[1] is not pin_model:
        if len(kept_owners) >= _KEPT_OWNERS:
            kept_owners.pop(next(iter(kept_owners)))
        last = kept_owners[id(moved_at)] = (moved_at, pin_model, {})
    owners: dict[str, int] = last[2]

    def owner(link: str) -> int:
        """The lane of ``link`` (-1: of none)."""
        found = owners.get(link)
        if found is None:
            jid = (int(pin_model.frames[pin_model.getFrameId(link)].parentJoint)
                   if pin_model.existFrame(link) else 0)
            found = owners[link] = (-1 if jid == 0 else int(moved_at[jid]) if moved_at[jid] >= 0
                                    else int(carried_at[jid]))
        return found

    holds = _holds(scene, lanes, owner)
    if not holds:
        return None
    t0, t1 = times
    # Where an object is taken or let go it is where it was held: a stretch shorter than
    # rounding (two lanes' motions starting together) is its neighbour's.
    points = sorted({t for found in holds.values() for h in found for t in (h.start, h.end)
                     if t0 + _INSTANT < t < t1 - _INSTANT})
    points = [t0, *(t for k, t in enumerate(points)
                    if k == 0 or t - points[k - 1] > _INSTANT), t1]
    model = scene.robot
    moving = {n for lane in lanes for m in lane.motions for n in m.trajectory.names}
    poses = _poses(scene.checker.robot_geometry)
    lane_joints: dict[int, set[str]] = {}  # the joints each lane's motions move

    def world(hold: _Hold, at_end: bool) -> SceneObject:
        """``hold``'s object where it lies when it is set down (``at_end``) or taken:
        its link's pose where its motion leaves (takes) it, the rest of the state then
        (as ``scene`` has it where it lies there too: :func:`_as_in`)."""
        link = hold.obj.attached_to
        assert link is not None
        motion, row = (hold.released if at_end else hold.taken) or (None, 0)
        names = motion.trajectory.names if motion is not None else ()
        chain, columns, rest = _chain(model, link, names)
        key: tuple[object, ...]
        own = lanes[hold.lane].motions
        if hold.lane not in lane_joints:
            lane_joints[hold.lane] = _joints(own)
        if motion is not None and not (moving - lane_joints[hold.lane]).intersection(chain):
            # Its lane's joints alone move the link: where its motions leave them.
            q = np.array(scene.state, dtype=float)
            _lane_rest(model, own, motion, q, rest)
            q[state_columns(model, names)] = motion.trajectory.positions[row]
            q = model.apply_mimic(q)
            # Its lane resting so, the object held as the scene has it lies there.
            freezes[hold.obj.name] = (hold.lane, columns, q[columns], hold.obj)
            key = (id(motion.trajectory), row, hold.obj, q[rest].tobytes())
            found = poses.get(key)
            if found is not None and found[0] is motion.trajectory:
                return _as_in(scene, found[1])
        else:  # other lanes' joints carry it: the state then
            q = np.array(state_at(hold.end if at_end else hold.start), dtype=float)
            if motion is not None:
                q[state_columns(model, names)] = motion.trajectory.positions[row]
                q = model.apply_mimic(q)
        if motion is None or moving.difference(names).intersection(chain):
            key = (link, q[columns].tobytes(), hold.obj)
            found = poses.get(key)
            if found is not None:
                return _as_in(scene, found[1])
        data = _data(model)
        frame = model.frame_id(link)
        pin.forwardKinematics(model.model, data, model.to_pin(q))
        pose = Pose.from_se3(pin.updateFramePlacement(model.model, data, frame)
                             * hold.obj.pose.se3)
        lying = _as_in(scene, replace(hold.obj, pose=pose, attached_to=None, touch_links=()))
        if len(poses) >= _KEPT_POSES:
            poses.pop(next(iter(poses)))
        poses[key] = (motion.trajectory if motion is not None else None, lying)
        return lying

    spans: list[tuple[tuple[object, ...], list[SceneObject], dict[str, int], float, float,
                      dict[str, _Freeze]]] = []
    for a, b in zip(points, points[1:] if len(points) > 1 else [t1]):
        mid = 0.5 * (a + b)
        objects: list[SceneObject] = []
        lying: dict[str, int] = {}
        freezes: dict[str, _Freeze] = {}
        for name, found in holds.items():
            now = [h for h in found if h.start <= mid <= h.end]
            if now:
                objects.append(now[0].obj)
                continue
            before = [h for h in found if h.end < mid]
            hold = before[-1] if before else next(h for h in found if h.start > mid)
            objects.append(world(hold, bool(before)))
            lying[name] = hold.lane
        key: tuple[object, ...] = tuple((o, lying.get(o.name)) for o in objects)
        if spans and spans[-1][0] == key:
            spans[-1] = (*spans[-1][:4], b, spans[-1][5])
        else:
            spans.append((key, objects, lying, a, b, freezes))
    # An object as the scene verified has it in every stretch: steady (walked once over
    # the whole window in that scene); the others change.
    steady = {name for name in holds
              if name in scene and all(scene.object(name) in objects for _, objects, *_ in spans)
              and len({lying.get(name) for _, _, lying, *_ in spans}) == 1}
    resting = {name: lane for name, lane in spans[0][2].items() if name in steady}
    if len(steady) == len(holds):
        return HeldObjects(frozenset(holds), frozenset(steady) - set(resting), resting, ())
    kept = _kept(scene.checker.robot_geometry)
    stretches = []
    snapshot = None
    changing = set(holds) - steady
    for key, objects, lying, a, b, freezes in spans:
        differ = {o.name for o in objects if o.name not in scene or scene.object(o.name) != o}
        frozen = _frozen(scene, differ, changing, freezes)
        if not differ or frozen is not None:
            # The scene verified holds them so (at the run's present, mostly), or holds
            # those that lie as their lane holds them where it rests: itself (that lane
            # resting there, its joints frozen).
            stretches.append(Stretch(a, b, scene, lying, frozen))
            continue
        if snapshot is None:
            snapshot = scene.snapshot()
            bodies = set(holds) | set(model.link_names)
            allowed = tuple(sorted(p for p in snapshot.allowed
                                   if (p[0] in holds or p[1] in holds)
                                   and p[0] in bodies and p[1] in bodies))
        full = (repr(getattr(scene, "options", None)), key, allowed)
        copy = kept.pop(full, None)
        if copy is None:
            copy = scene.copy()
            copy.restore(replace(snapshot, objects=tuple(objects), allowed=allowed))
            if len(kept) >= _KEPT:
                kept.pop(next(iter(kept)))
        kept[full] = copy  # the latest last
        stretches.append(Stretch(a, b, copy, lying))
    return HeldObjects(frozenset(holds), frozenset(steady) - set(resting), resting,
                       tuple(stretches))


def lanes_state(scene: Scene, lanes: Sequence[Lane], t: float) -> np.ndarray:
    """The full state at ``t`` (s, the lanes' clock): each lane's joints where its
    motions put them then (before a motion starts, where it starts; after it ends, where
    it ended), every other joint at ``scene.state``."""
    model = scene.robot
    q = scene.state.copy()
    for lane in lanes:
        ordered = sorted(lane.motions, key=lambda m: m.start)
        started = [m for m in ordered if m.start <= t]
        # A joint is where the latest motion started moving it puts it; one that no
        # motion started moves, where the first to move it starts.
        placed: set[str] = set()
        for motion in [*reversed(started), *ordered[len(started):]]:
            trajectory = motion.trajectory
            names = [n for n in trajectory.names if n not in placed]
            if not names:
                continue
            at = min(t - motion.start, trajectory.duration) if motion.start <= t else 0.0
            columns = [trajectory.names.index(n) for n in names]
            q[model.indices(names)] = [np.interp(at, trajectory.times,
                                                 trajectory.positions[:, j]) for j in columns]
            placed.update(names)
    return model.apply_mimic(q)


def _frozen(scene: Scene, differ: set[str], changing: set[str],
            freezes: Mapping[str, _Freeze]) -> tuple[np.ndarray, np.ndarray] | None:
    """The state columns and values at which the lane of the objects ``differ`` (those
    not as ``scene`` has them) holds them, as the scene has them attached, where they lie
    (:class:`Stretch`); None where that is not so for all, or other objects change."""
    found = [freezes.get(name) for name in differ]
    if not differ or differ != changing or any(f is None for f in found):
        return None
    held = [f for f in found if f is not None]
    if len({f[0] for f in held}) != 1 or any(
            f[3].name not in scene or scene.object(f[3].name) != f[3] for f in held):
        return None
    columns = np.concatenate([f[1] for f in held])
    values = np.concatenate([f[2] for f in held])
    order = np.argsort(columns, kind="stable")
    columns, values = columns[order], values[order]
    same = columns[1:] == columns[:-1]
    if np.any(values[1:][same] != values[:-1][same]):
        return None  # two of its states
    return columns, values


def _as_in(scene: Scene, obj: SceneObject) -> SceneObject:
    """World object ``obj`` as ``scene`` has it where it lies there too (to rounding: it
    was set down there), else ``obj``."""
    if obj.name not in scene:
        return obj
    there = scene.object(obj.name)
    if there is obj:
        return obj
    if there.attached or there.shape != obj.shape:
        return obj
    a, b = there.pose, obj.pose
    turn = min(np.abs(np.subtract(a.quat, b.quat)).max(), np.abs(np.add(a.quat, b.quat)).max())
    if np.abs(np.subtract(a.xyz, b.xyz)).max() <= _SAME and turn <= _SAME:
        return there
    return obj


def _kept(part: object) -> dict[tuple[object, ...], Scene]:
    """This thread's stretch scenes of a robot (``part``: its checkers' robot geometry)."""
    return _per_thread("scenes", part)


def _per_thread(attr: str, part: object) -> dict[tuple[object, ...], Any]:
    """This thread's table ``attr`` of a robot (``part``: its checkers' robot geometry),
    kept while ``part`` lives."""
    found: weakref.WeakKeyDictionary[object, dict[tuple[object, ...], Any]] | None = \
        getattr(_LOCAL, attr, None)
    if found is None:
        found = weakref.WeakKeyDictionary()
        setattr(_LOCAL, attr, found)
    kept = found.get(part)
    if kept is None:
        kept = found[part] = {}
    return kept


def _data(model: RobotModel) -> pin.Data:
    """This thread's pinocchio data of ``model`` (kept)."""
    found: tuple[RobotModel, pin.Data] | None = getattr(_LOCAL, "data", None)
    if found is None or found[0] is not model:
        found = _LOCAL.data = (model, model.model.createData())
    return found[1]


def _joints(motions: Sequence[TimedMotion]) -> set[str]:
    """The joints ``motions`` move."""
    return {n for m in motions for n in m.trajectory.names}


def _lane_rest(model: RobotModel, motions: Sequence[TimedMotion], motion: TimedMotion,
               q: np.ndarray, columns: np.ndarray) -> None:
    """Set the state ``columns`` of ``q`` that ``motion`` does not move where the other
    ``motions`` of its lane leave them while it runs (the latest to move one before it
    ends there, else the first after starts there; else as they are)."""
    if not len(columns):
        return
    todo = {model.joint_names[c]: c for c in columns.tolist()}  # the columns not set yet
    earlier = sorted((m for m in motions if m.start <= motion.start and m is not motion),
                     key=lambda m: m.start, reverse=True)
    later = sorted((m for m in motions if m.start > motion.start), key=lambda m: m.start)
    for other, row in [*((m, -1) for m in earlier), *((m, 0) for m in later)]:
        names = other.trajectory.names
        found = [(k, todo.pop(n)) for k, n in enumerate(names) if n in todo]
        if found:
            positions = other.trajectory.positions[row]
            for k, column in found:
                q[column] = positions[k]
            if not todo:
                return


def _chain(model: RobotModel, link: str, names: Sequence[str]
           ) -> tuple[frozenset[str], np.ndarray, np.ndarray]:
    """The joints that move ``link`` (by name), their state columns, and those of them
    not among ``names`` (kept)."""
    key = (id(model), link, tuple(names))
    chains: dict[tuple[object, ...], tuple[RobotModel, tuple[frozenset[str], np.ndarray,
                                                            np.ndarray]]] | None = \
        getattr(_LOCAL, "chains", None)
    if chains is None:
        chains = _LOCAL.chains = {}
    found = chains.get(key)
    if found is not None and found[0] is model:
        return found[1]
    pin_model = model.model
    jid = int(pin_model.frames[pin_model.getFrameId(link)].parentJoint)
    chain = [str(pin_model.names[j]) for j in pin_model.supports[jid] if j > 0]
    known = [n for n in chain if n in model.joint_names]
    made = (frozenset(chain), model.indices(known),
            model.indices([n for n in known if n not in names]))
    if len(chains) >= _KEPT_POSES:
        chains.pop(next(iter(chains)))
    chains[key] = (model, made)
    return made


def _poses(part: object) -> dict[tuple[object, ...], tuple[object, SceneObject]]:
    """This thread's objects set down or taken (:func:`held_objects`), of a robot
    (``part``: its checkers' robot geometry), by their motion's trajectory (kept with
    it) or their link's joints' state, and the object held."""
    return _per_thread("poses", part)


def _holds(scene: Scene, lanes: Sequence[Lane], owner: Callable[[str], int]
           ) -> dict[str, list[_Hold]]:
    """Per named object, when which lane holds it, in time order (module text)."""
    # Per object: [lane, start, end, object, taken, released, last motion].
    rows: dict[str, list[list[Any]]] = {}
    lasts: list[TimedMotion | None] = []
    for index, lane in enumerate(lanes):
        previous = None
        for motion in sorted(lane.motions, key=lambda m: m.start):
            for obj in motion.held or ():
                if obj.attached_to is None or owner(obj.attached_to) != index:
                    continue  # another lane's: only its own lane's say counts
                found = rows.setdefault(obj.name, [])
                last = found[-1] if found else None
                if (last is not None and previous is not None and last[6] is previous
                        and last[0] == index and (last[3] is obj or last[3] == obj)):
                    # In its hand between the two.
                    last[2], last[5], last[6] = motion.end, (motion, -1), motion
                else:
                    found.append([index, motion.start, motion.end, obj, (motion, 0),
                                  (motion, -1), motion])
            previous = motion
        lasts.append(previous)
    # After its last motion an arm holds what the scene has attached to its links.
    listed = {o.name for lane in lanes for m in lane.motions for o in m.held or ()}
    for obj in scene.attached_objects():
        assert obj.attached_to is not None
        index = owner(obj.attached_to)
        if index < 0 or obj.name not in listed:
            continue
        found = rows.setdefault(obj.name, [])
        last = found[-1] if found else None
        final = lasts[index]
        if last is not None and final is not None and last[6] is final and last[3] == obj:
            last[2] = np.inf
        else:  # taken where the lane rests
            resting = (final, -1) if final is not None else None
            found.append([index, final.end if final is not None else -np.inf, np.inf, obj,
                          resting, resting, final])
    holds: dict[str, list[_Hold]] = {}
    for name, found in rows.items():
        found.sort(key=lambda h: h[1])
        for k in range(len(found) - 1):  # a hold at rest ends where another one begins
            found[k][2] = min(found[k][2], found[k + 1][1])
        holds[name] = [_Hold(*row[:6]) for row in found]
    return holds
