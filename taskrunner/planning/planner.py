"""Collision-free joint-space paths with OMPL.

:class:`MotionPlanner` plans a group of a scene's robot model from a start state to one of
several goals. The group's joints form an OMPL real-vector space bounded by the joint
limits; every other joint stays where the start state has it. States are checked by the
scene's collision checker (self, world and attached objects), every
``longest_valid_segment`` along each edge (compiled bounding volumes first, coal only on
the pairs they cannot clear: :mod:`taskrunner.scene.screen`). The path found is
shortcut, then verified exactly by conservative advancement (per-joint lever arms bound
how far any point of any body moves between checks, coal distances against the scene's
geometry: :mod:`taskrunner.scene.path_verifier`); with timing, the sampled trajectory that is
executed is verified the same way. A path or trajectory that fails is never returned: the
search is repeated with a finer planning segment, or :class:`PlanningError` is raised.

The goal states come from :mod:`taskrunner.planning.goal_states`, the OMPL search from
:mod:`taskrunner.planning.ompl_search` (the order of an edge's checks:
:mod:`taskrunner.planning.edge_order`), the shortcutting from
:mod:`taskrunner.planning.shortcut`.

References: Kuffner & LaValle, "RRT-Connect: An Efficient Approach to Single-Query Path
Planning", ICRA 2000; Şucan, Moll & Kavraki, "The Open Motion Planning Library", 2012;
Schwarzer, Saha & Latombe, "Adaptive dynamic collision checking for single and multiple
articulated robots in complex environments", IEEE T-RO 2005 (exact path checking).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from taskrunner.errors import (
    GoalInCollisionError,
    IkFailedError,
    InvalidStateError,
    NoDirectPathError,
    PlanningError,
    PlanningTimeoutError,
    StartInCollisionError,
)
from taskrunner.kinematics import IkSolver
from taskrunner.planning import edge_order
from taskrunner.planning.goal_states import goal_states
from taskrunner.planning.ompl_search import import_ompl, search_path
from taskrunner.planning.request import (
    PlannerOptions,
    PlanRequest,
    PlanResult,
    group_planner,
)
from taskrunner.planning.shortcut import shortcut_path
from taskrunner.planning.timing import TimingOptions, parameterize_path, trajectory_json
from taskrunner.robot.model import Group
from taskrunner.scene import Scene
from taskrunner.scene.collision import VERIFY_MARGIN
from taskrunner.types import JointPath, JointTrajectory

if TYPE_CHECKING:  # numba, with the verifier: loaded when a path is first verified
    from taskrunner.scene.coalpath import CoalPathVerifier, CoalScreen
    from taskrunner.scene.path_verifier import PathVerification
    from taskrunner.scene.screen import StateScreen

__all__ = ["MotionPlanner", "first_invalid_state", "interpolate_path"]

_REFINEMENTS = 3
"""Searches of a request at least: its segment, then halved while a path found collides."""
FINEST_SEGMENT = 0.0125
"""rad: the finer searches halve the segment at least down to this."""


def refined_segments(segment: float) -> list[float]:
    """The planning segments of a request's searches, each half the one before: at
    least :data:`_REFINEMENTS` of them, and as many as it takes to reach
    :data:`FINEST_SEGMENT`."""
    count = max(_REFINEMENTS, 1 + math.ceil(math.log2(segment / FINEST_SEGMENT) - 1e-9))
    return [segment / 2**k for k in range(count)]


def interpolate_path(waypoints: np.ndarray, resolution: float) -> np.ndarray:
    """Waypoints with points inserted so no joint moves more than ``resolution`` per step."""
    out = [waypoints[:1]]
    for a, b in zip(waypoints[:-1], waypoints[1:]):
        steps = max(1, int(np.ceil(np.max(np.abs(b - a)) / resolution)))
        t = np.linspace(0.0, 1.0, steps + 1)[1:, None]
        out.append(a + t * (b - a))
    return np.vstack(out)


def first_invalid_state(
    is_valid: Callable[[np.ndarray], bool], waypoints: np.ndarray, resolution: float
) -> np.ndarray | None:
    """The first state along the path (checked every ``resolution`` rad) that is invalid."""
    for q in interpolate_path(waypoints, resolution):
        if not is_valid(q):
            return q
    return None


class MotionPlanner:
    """Plans paths for the groups of a scene's robot.

    The planner reads the scene (objects, attachments, allowed collisions, current state)
    at every request; it keeps IK solvers between requests.

    Args:
        scene: the planning scene.
        compiled: check with the compiled kernels (the screen and the path verifier of
            :mod:`taskrunner.scene.screen` and :mod:`taskrunner.scene.path_verifier`), or, False,
            with coal alone (:mod:`taskrunner.scene.coalpath`: the same verdicts for
            states, the same guarantee for paths, slower) while the kernels compile
            (:mod:`taskrunner.planning.warmup`). An attribute: set between requests.
    """

    def __init__(self, scene: Scene, compiled: bool = True) -> None:
        self.scene = scene
        self.compiled = compiled
        self._ik: dict[tuple[str, str | None], IkSolver] = {}
        self._group_columns: dict[str, tuple[slice | np.ndarray, bool]] = {}
        self._coal: tuple[object, float, CoalPathVerifier, CoalScreen] | None = None

    # ------------------------------------------------------------------ public
    def plan(self, request: PlanRequest, should_stop: Callable[[], bool] | None = None) -> PlanResult:
        """Plan a path for ``request`` (and time it, with ``request.timing``).

        Args:
            request: group, goal(s), optional start state and options.
            should_stop: polled while planning; returning True cancels the request.

        Raises:
            UnknownNameError: an unknown group, joint, link or named pose.
            InvalidStateError: the start or a goal is outside the limits or not of the group.
            StartInCollisionError, GoalInCollisionError: with the colliding pairs.
            IkFailedError: no goal pose is reachable.
            PlanningTimeoutError: no path within the time and attempts.
            PlanningCancelledError: ``should_stop`` said so.
            PlanningError: the path cannot be timed (with ``request.timing``).
        """
        if not request.options.planner:  # the group's default (ompl_planning.yaml)
            planner = group_planner(self.scene.robot.group(request.group))
            request = replace(request, options=replace(request.options, planner=planner))
        result = self._plan(request, should_stop)
        if not self.compiled:
            result = replace(result, compiled=False)
        if request.timing is None:
            return result
        trajectory, verified = self._timed(result, request.timing, request.options)
        encoded = trajectory_json(trajectory) if request.trajectory_json else None
        return replace(result, trajectory=trajectory, trajectory_json=encoded,
                       verify_queries=result.verify_queries + verified.distance_queries,
                       verify_time=result.verify_time + verified.seconds)

    def verify_states(self, states: np.ndarray, margin: float) -> PathVerification:
        """Verify the polyline through full state vectors ``states`` against the scene
        (conservative advancement, see :mod:`taskrunner.scene.path_verifier`; ``margin`` in m)."""
        if not self.compiled:
            return self._coal_checks(margin)[0].verify(states)
        return self.scene.path_verifier(margin).verify(states)

    def _coal_checks(self, margin: float) -> tuple[CoalPathVerifier, CoalScreen]:
        """The checks with coal alone for the scene as it is now (kept until it changes)."""
        checker = self.scene.checker
        kept = self._coal
        if kept is None or kept[0] is not checker or kept[1] != margin:
            from taskrunner.scene.coalpath import CoalPathVerifier, CoalScreen

            robot = self.scene.robot
            kept = self._coal = (checker, margin, CoalPathVerifier(robot, checker, margin),
                                 CoalScreen(robot, checker))
        return kept[2], kept[3]

    def _full_states(self, start: np.ndarray, names: tuple[str, ...], rows: np.ndarray
                     ) -> np.ndarray:
        model = self.scene.robot
        states = np.repeat(start[None, :], len(rows), axis=0)
        states[:, model.indices(names)] = rows
        for q in states:
            model.apply_mimic(q)
        return states

    def _timed(self, result: PlanResult, timing: TimingOptions, options: PlannerOptions
               ) -> tuple[JointTrajectory, PathVerification]:
        """Time the path and verify the sampled trajectory (what is executed: the spline
        leaves the checked polyline by up to ``max_deviation_rad``). Where it collides,
        time again closer to the polyline."""
        model = self.scene.robot
        tried = timing
        for _ in range(3):
            trajectory = parameterize_path(model, result.path, tried)
            if _on_segment(np.asarray(result.path.waypoints), trajectory.positions):
                # A straight line timed in closed form: its samples lie on the segment the
                # path's verification covered already.
                from taskrunner.scene.path_verifier import PathVerification as Verified

                return trajectory, Verified(True, 0, 0, 0.0)
            verified = self.verify_states(
                self._full_states(result.start, trajectory.names, trajectory.positions),
                options.verify_margin)
            if verified.valid:
                return trajectory, verified
            step = tried.densify_step_rad / 4
            tried = replace(tried, densify_step_rad=step, max_deviation_rad=step)
        raise PlanningError(
            f"the timed trajectory of the path found collides ({_pair(verified)} at sample "
            f"{verified.fraction:.1f}), even timed within {tried.densify_step_rad * 4:g} rad "
            "of the verified path")

    def _plan(self, request: PlanRequest, should_stop: Callable[[], bool] | None) -> PlanResult:
        t_start = time.perf_counter()
        model = self.scene.robot
        options = request.options
        assert options.planner is not None  # plan() has put in the group's default
        group = model.group(request.group)
        if len(group.joint_names) == 0:
            raise InvalidStateError(f"group {group.name!r} has no joints to plan for")
        start = self._start_state(request, group)
        candidates = self._goal_states(request, group, start)
        idx = group.joint_indices
        for goal_index, q_goal in candidates:
            if np.max(np.abs(q_goal[idx] - start[idx])) < 1e-9:
                path = JointPath(group.joint_names, np.vstack([start[idx], q_goal[idx]]))
                return PlanResult(path, start, q_goal, goal_index, options.planner, 0.0, 0.0,
                                  time.perf_counter() - t_start, 0)
        planning_time = simplify_time = verify_time = 0.0
        checks = queries = 0
        if options.direct:
            direct = self._direct(group, start, candidates, options)
            checks += direct.checks
            verify_time += direct.verify_time
            queries += direct.queries
            if direct.goal is not None:
                goal_index, q_goal = direct.goal
                path = JointPath(group.joint_names, np.vstack([start[idx], q_goal[idx]]))
                return PlanResult(path, start, q_goal, goal_index, options.planner, 0.0, 0.0,
                                  time.perf_counter() - t_start, checks, direct=True,
                                  verify_queries=queries, verify_time=verify_time)
            if options.direct_only:
                raise NoDirectPathError(
                    f"the straight line from the start to each of the {len(candidates)} goal "
                    f"states of group {group.name!r} is blocked (direct_only: no search)")
        failure: PathVerification | None = None
        # The searches of a request (its attempts, and the finer searches after a path
        # is turned down) share one budget: planning_time per attempt.
        import_ompl()  # imported before the clock starts (the first import takes a while)
        deadline = time.perf_counter() + options.planning_time * options.attempts
        segments = refined_segments(options.longest_valid_segment)
        for refinement, segment in enumerate(segments):
            # A path checked every longest_valid_segment may clip a thin obstacle that the
            # exact verification then finds: search again with a finer segment.
            tried = options if refinement == 0 else replace(
                options, longest_valid_segment=segment, seed=options.seed + 1000 * refinement)
            if refinement and time.perf_counter() >= deadline:
                assert failure is not None
                raise PlanningTimeoutError(
                    f"every path found for group {group.name!r} collided when verified "
                    f"exactly ({_pair(failure)}), and the request's "
                    f"{options.planning_time * options.attempts:g} s of search ran out "
                    f"before a finer search (segment {tried.longest_valid_segment:g} rad)")
            found, seconds, count = self._search(group, start, candidates, tried, should_stop,
                                                 deadline)
            planning_time += seconds
            checks += count
            t_simplify = time.perf_counter()
            waypoints, verifications = self._simplified(group, start, found, tried)
            simplify_time += time.perf_counter() - t_simplify
            for verification in verifications:
                verify_time += verification.seconds
                queries += verification.distance_queries
            if waypoints is not None:
                break
            failure = verifications[-1]
        else:
            assert failure is not None
            raise PlanningError(
                f"every path found for group {group.name!r} collided when verified exactly "
                f"({_pair(failure)}), down to a planning segment of "
                f"{segments[-1]:g} rad")
        end = start.copy()
        end[idx] = waypoints[-1]
        model.apply_mimic(end)
        goal_index = min(candidates, key=lambda c: float(np.max(np.abs(c[1][idx] - end[idx]))))[0]
        return PlanResult(JointPath(group.joint_names, waypoints), start, end, goal_index,
                          options.planner, planning_time, simplify_time - verify_time,
                          time.perf_counter() - t_start, checks, searches=refinement + 1,
                          verify_queries=queries, verify_time=verify_time)

    # ------------------------------------------------------------------ states
    def _start_state(self, request: PlanRequest, group: Group) -> np.ndarray:
        model = self.scene.robot
        if request.start is None:
            start = self.scene.state.copy()
        else:
            start = np.array(request.start, dtype=float)
            if start.shape != (model.nq,):
                raise InvalidStateError(f"'start' must have {model.nq} values, one per joint "
                                        f"of {model.name!r} (got shape {start.shape})")
            model.apply_mimic(start)
        bad = model.limit_violations(start)
        if bad:
            raise InvalidStateError("start state outside the joint limits: " + "; ".join(bad))
        # The checker itself, not the search's screen: a request answered without a search
        # (a group already at its goal) loads no compiled kernels.
        if self.scene.in_collision(start):
            contacts = self.scene.collisions(start)
            pairs = [(c.a, c.b) for c in contacts]
            raise StartInCollisionError(
                f"start state of group {group.name!r} is in collision: " + _describe(contacts)
                + self.scene.geometry_note(contacts[:3]), pairs)
        return start

    def _goal_states(self, request: PlanRequest, group: Group, start: np.ndarray
                     ) -> list[tuple[int, np.ndarray]]:
        """Valid goal states (full vectors) with the index of the goal they satisfy."""
        model = self.scene.robot
        valid: list[tuple[int, np.ndarray]] = []
        rejected: list[tuple[int, np.ndarray]] = []
        unreachable: list[IkFailedError] = []
        for index, goal in enumerate(request.goals):
            try:
                candidates = goal_states(goal, group, start, request.options, self.scene,
                                         self._solver)
            except IkFailedError as exc:
                # With several goals, one out of reach is fine as long as another is not.
                unreachable.append(exc)
                continue
            for q in candidates:
                bad = model.limit_violations(q)
                if bad:
                    raise InvalidStateError(f"goal {index} outside the joint limits: "
                                            + "; ".join(bad))
                (rejected if self.scene.in_collision(q) else valid).append((index, q))
        if not valid and not rejected:
            raise unreachable[0]
        if not valid:
            contacts = self.scene.collisions(rejected[0][1])
            raise GoalInCollisionError(
                f"every goal state of group {group.name!r} is in collision ("
                f"{len(rejected)} checked); first: " + _describe(contacts)
                + self.scene.geometry_note(contacts[:3]), [(c.a, c.b) for c in contacts])
        return valid

    def _solver(self, group: Group, frame: str | None) -> IkSolver:
        """The IK solver of ``group`` for ``frame`` (kept between requests)."""
        key = (group.name, frame)
        if key not in self._ik:
            self._ik[key] = IkSolver(self.scene.robot, group.name, frame=frame)
        return self._ik[key]

    # ------------------------------------------------------------------ search
    def _direct(self, group: Group, start: np.ndarray, goals: list[tuple[int, np.ndarray]],
                options: PlannerOptions) -> _Direct:
        """The first goal state (in the request's order: callers list the goals they
        prefer first) whose straight line from ``start`` passes the search's edge check
        and then the exact verification."""
        idx = group.joint_indices
        out = _Direct()
        count = [0]
        edge_valid = self._edge_validity(group, start, options.longest_valid_segment, count,
                                         margin=options.verify_margin)
        for index, q_goal in goals:
            if not edge_valid(start[idx], q_goal[idx]):
                continue
            verification = self.verify_states(np.vstack([start, q_goal]), options.verify_margin)
            out.verify_time += verification.seconds
            out.queries += verification.distance_queries
            if verification.valid:
                out.goal = (index, q_goal)
                break
        out.checks = count[0]
        return out

    def _checks(self, group: Group, start: np.ndarray, resolution: float,
                known: set[bytes] | None = None, margin: float = VERIFY_MARGIN
                ) -> tuple[Callable[[np.ndarray], bool],
                           Callable[[np.ndarray, np.ndarray], bool], list[int]]:
        """A state check and an edge check over the group's values (an edge's first
        state is taken as checked), and a counter of the states they checked. ``known``:
        see :meth:`_edge_validity` (the exact checks only; states found valid by the
        state check are added). ``margin``: the request's verification margin (see
        :meth:`_scan`)."""
        # One compiled segment scan for both (a state is a segment of one step).
        segment = self._segment_scan(group, start, resolution, margin)
        exact, count = self._validity(group, start, margin, segment)
        exact_edge = self._edge_validity(group, start, resolution, count, known, margin, segment)
        if known is None:
            return exact, exact_edge, count

        def remembered(values: np.ndarray) -> bool:
            key = values.tobytes()
            if key in known:
                return True
            if exact(values):
                known.add(key)
                return True
            return False

        return remembered, exact_edge, count

    def _state_screen(self, margin: float) -> StateScreen | CoalScreen:
        """The scene's state screen (:meth:`Scene.state_screen`: the checker's verdicts,
        with coal only on the pairs that cheap compiled bounds cannot clear), built on the
        path verifier of the request's ``margin``, which verifies the path afterwards;
        not :attr:`compiled`: the checker's scans."""
        if not self.compiled:
            return self._coal_checks(margin)[1]
        return self.scene.state_screen(margin)

    def _scan(self, margin: float) -> Callable[[np.ndarray], int]:
        """The index of the first of some full states (the rows of a C-contiguous array)
        in collision, or -1 (:meth:`_state_screen`)."""
        return self._state_screen(margin).scanner()

    def _validity(self, group: Group, start: np.ndarray, margin: float = VERIFY_MARGIN,
                  segment: Callable[[np.ndarray, np.ndarray, int], tuple[int, int]] | None = None
                  ) -> tuple[Callable[[np.ndarray], bool], list[int]]:
        """A fast validity check over the group's values, and a call counter. ``segment``:
        :meth:`_segment_scan`'s for the same start and margin, if any (a state is then
        checked as a segment of one step)."""
        count = [0]
        if segment is not None:
            def state_valid(values: np.ndarray) -> bool:
                count[0] += 1
                return segment(values, values, 0)[0] == -1

            return state_valid, count
        model = self.scene.robot
        scan = self._scan(margin)
        q = start.copy()
        rows = q[None, :]  # a view: the state as the one row the scan takes
        idx = group.joint_indices
        mimic = model.mimic_follows(idx)

        def is_valid(values: np.ndarray) -> bool:
            count[0] += 1
            q[idx] = values
            if mimic:
                model.apply_mimic(q)
            return scan(rows) < 0

        return is_valid, count

    def _columns(self, group: Group) -> tuple[slice | np.ndarray, bool]:
        """The group's columns of a state (a slice where they are contiguous: cheaper than
        a gather) and whether a mimic joint follows one of them (kept per group)."""
        found = self._group_columns.get(group.name)
        if found is None:
            idx = group.joint_indices
            columns: slice | np.ndarray = idx
            if len(idx) and np.array_equal(idx, np.arange(idx[0], idx[0] + len(idx))):
                columns = slice(int(idx[0]), int(idx[0]) + len(idx))
            found = self._group_columns[group.name] = (columns,
                                                       self.scene.robot.mimic_follows(idx))
        return found

    def _segment_scan(self, group: Group, start: np.ndarray, resolution: float, margin: float
                      ) -> Callable[[np.ndarray, np.ndarray, int], tuple[int, int]] | None:
        """The screen's segment scan (:meth:`StateScreen.segment_scanner`) of the group's
        values from ``start``, the fractions from the process's table; None where the
        group's columns are not contiguous, a mimic joint follows one, or the screen runs
        coal alone."""
        columns, mimic = self._columns(group)
        if not isinstance(columns, slice) or mimic:
            return None
        return self._state_screen(margin).segment_scanner(start.copy(), columns.start,
                                                          edge_order.FRACTIONS, resolution,
                                                          edge_order.fill_fractions)

    def _edge_validity(self, group: Group, start: np.ndarray, resolution: float,
                       count: list[int], known: set[bytes] | None = None,
                       margin: float = VERIFY_MARGIN,
                       segment: Callable[[np.ndarray, np.ndarray, int], tuple[int, int]]
                       | None = None) -> Callable[[np.ndarray, np.ndarray], bool]:
        """An edge check over the group's values: the edge's end, then the states every
        ``resolution`` (max over joints) in between, coarse to fine (see
        :func:`~taskrunner.planning.edge_order.bisection_order`); the edge's first state
        is taken as checked. One Python call per edge: the states are interpolated
        together.

        ``known``: the group values (``tobytes()``) of states already found valid: an
        edge's end found there is not checked again (RRT-Connect's goal tree checks
        edges towards nodes of its own tree). Ends found valid are added. ``segment``:
        :meth:`_segment_scan`'s for the same arguments, made here if not given."""
        model = self.scene.robot
        screen = self._state_screen(margin)
        base = start.copy()
        columns, mimic = self._columns(group)
        # Per number of steps: the fractions of the states along the edge, the end's first
        # (1.0), then the inner states coarse to fine; and the states' rows (one scan for
        # the end and the inner states).
        orders: dict[int, tuple[np.ndarray, np.ndarray]] = {}
        # Contiguous columns and no mimic joint to follow: the states are interpolated in
        # the screen's compiled loop, as far as the first collision.
        interpolated = isinstance(columns, slice) and not mimic
        first = columns.start if isinstance(columns, slice) else 0
        # ... and there, the step count too, the fractions taken from the process's table.
        if segment is None and interpolated:
            segment = self._segment_scan(group, start, resolution, margin)
        scans: list[Callable[..., int]] = []  # the others' scan, made when first needed

        def edge_valid(a: np.ndarray, b: np.ndarray) -> bool:
            if segment is not None:
                known_end = known is not None and b.tobytes() in known
                begin = 1 if known_end else 0
                hit, steps = segment(a, b, begin)
                if hit != -2:  # else longer than the table: the states made below
                    if begin < steps:
                        count[0] += steps - begin if hit < 0 else hit - begin + 1
                    if known is not None and not known_end and hit != 0:
                        known.add(b.tobytes())
                    return hit < 0
            steps = max(1, math.ceil(max(map(abs, (b - a).tolist())) / resolution))
            cached = orders.get(steps)
            if cached is None:
                fractions = np.concatenate([[1.0], edge_order.bisection_order(steps) / steps])
                rows = np.empty((steps, len(base)))
                rows[:] = base
                cached = orders[steps] = (fractions, rows)
            fractions, rows = cached
            key = b.tobytes() if known is not None else b""
            end = known is None or key not in known
            begin = 0 if end else 1
            if begin >= steps:
                return True
            if not scans:
                scans.append(screen.line_scanner() if interpolated else screen.scanner())
            if interpolated:
                hit = scans[0](rows, fractions, a, b, first, begin)
            else:
                states = rows[begin:]
                states[:, columns] = a + fractions[begin:, None] * (b - a)
                if end:
                    rows[0, columns] = b  # exactly the end (a + 1.0 * (b - a) may round)
                if mimic:
                    model.apply_mimic(states)
                hit = scans[0](states)
                hit = hit if hit < 0 else begin + hit
            count[0] += steps - begin if hit < 0 else hit - begin + 1
            if end and known is not None and hit != 0:
                known.add(key)
            return hit < 0

        return edge_valid

    def _search(self, group: Group, start: np.ndarray, goals: list[tuple[int, np.ndarray]],
                options: PlannerOptions, should_stop: Callable[[], bool] | None,
                deadline: float) -> tuple[np.ndarray, float, int]:
        """OMPL's search (:func:`~taskrunner.planning.ompl_search.search_path`) with this
        planner's state and edge checks."""
        def checks(known: set[bytes]) -> tuple[Callable[[np.ndarray], bool],
                                               Callable[[np.ndarray, np.ndarray], bool],
                                               list[int]]:
            return self._checks(group, start, options.longest_valid_segment, known,
                                options.verify_margin)

        return search_path(self.scene.robot, group, start, goals, options, should_stop,
                           deadline, checks)

    def _simplified(self, group: Group, start: np.ndarray, waypoints: np.ndarray,
                    options: PlannerOptions
                    ) -> tuple[np.ndarray | None, list[PathVerification]]:
        """Shortcut the path, then verify it exactly; fall back to the raw path if needed.
        None (with the verifications made) when both collide."""
        # The search's waypoints are valid states: edges ending at one skip that check.
        known = {np.ascontiguousarray(w, dtype=float).tobytes() for w in waypoints}
        _, edge_valid, _ = self._checks(group, start, options.longest_valid_segment, known,
                                        options.verify_margin)
        candidates = []
        if options.simplify and len(waypoints) > 2:
            candidates.append(shortcut_path(edge_valid, waypoints, options.seed))
        candidates.append(waypoints)
        verifications = []
        for candidate in candidates:
            verification = self.verify_states(
                self._full_states(start, group.joint_names, candidate), options.verify_margin)
            verifications.append(verification)
            if verification.valid:
                return candidate, verifications
        return None, verifications


@dataclass
class _Direct:
    """What :meth:`MotionPlanner._direct` found: the goal reached in a straight line
    (None: every line was blocked), the checks made and the verification's cost."""

    goal: tuple[int, np.ndarray] | None = None
    checks: int = 0
    queries: int = 0
    verify_time: float = 0.0


def _on_segment(waypoints: np.ndarray, samples: np.ndarray, tolerance: float = 1e-12) -> bool:
    """True when ``waypoints`` is one segment and every row of ``samples`` lies on it
    (within ``tolerance`` rad, or m, per joint)."""
    if len(waypoints) != 2 or samples.ndim != 2 or samples.shape[1] != waypoints.shape[1]:
        return False
    a, b = waypoints
    d = b - a
    length2 = float(d @ d)
    if length2 == 0.0:
        return bool(np.all(np.abs(samples - a) <= tolerance))
    t = np.clip((samples - a) @ d / length2, 0.0, 1.0)
    return bool(np.all(np.abs(samples - (a + t[:, None] * d)) <= tolerance))


def _pair(verification: PathVerification) -> str:
    if verification.pair is None:
        return "no contact"
    a, b = (name.rsplit("/", 1)[0] for name in verification.pair)
    return f"{a}–{b}"


def _describe(contacts) -> str:  # type: ignore[no-untyped-def]
    if not contacts:
        return "no contact reported"
    shown = ", ".join(f"{c.a}–{c.b}" for c in contacts[:3])
    more = f" and {len(contacts) - 3} more" if len(contacts) > 3 else ""
    return shown + more
