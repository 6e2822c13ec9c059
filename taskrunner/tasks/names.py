"""Static name checks of a task against its cell: groups, poses, joints, links, objects.

:func:`check_names` finds what a task names that the cell does not have — a group, a
named pose, a joint, a link or frame, an object — before anything is planned, and
returns every problem (it does not raise). Objects are followed in document order: the
cell's objects and the task's ``objects`` exist from the start, ``add_object`` adds one,
``remove_object`` takes it away. Reachability and collisions are the planner's business.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from pathlib import Path

from taskrunner.folders import FolderPolicy
from taskrunner.robot.cell import Cell, load_cell
from taskrunner.robot.model import Group, RobotModel
from taskrunner.tasks.expect import Expectation
from taskrunner.tasks.loader import load_task
from taskrunner.tasks.nodes import WORLD, Node, ObjectSpec, PoseSpec, TargetPose
from taskrunner.tasks.problem import Problem, did_you_mean
from taskrunner.tasks.spec import TaskSpec
from taskrunner.tasks.steps import (
    AddObjectStep,
    AttachStep,
    DetachStep,
    ExpectStep,
    GoStep,
    GripperStep,
    HandoffStep,
    MoveStep,
    ParallelStep,
    PickStep,
    PlaceStep,
    RemoveObjectStep,
    StepNode,
)
from taskrunner.taught import TaughtPoses
from taskrunner.textfile import file_problem

__all__ = ["arm_groups", "check_names", "gripper_group_of", "load_and_check", "moved_groups"]


def arm_groups(model: RobotModel) -> list[str]:
    """Groups that can pick: a tip link and an end effector."""
    return [g.name for g in model.groups.values() if g.tip_link and g.end_effector]


def gripper_group_of(model: RobotModel, arm: str) -> str | None:
    """The group that opens and closes ``arm``'s gripper: the group of the end effector
    whose parent group is ``arm`` (or of the arm's own end effector), if it has joints."""
    group = model.groups.get(arm)
    candidates = [ee for ee in model.end_effectors.values() if ee.parent_group == arm]
    if group is not None and group.end_effector in model.end_effectors:
        candidates.append(model.end_effectors[group.end_effector])
    for ee in candidates:
        gripper = model.groups.get(ee.group)
        if ee.group != arm and gripper is not None and gripper.joint_names:
            return ee.group
    return None


def moved_groups(step: StepNode, model: RobotModel) -> list[str]:
    """Groups of the cell that ``step`` (and the steps under it) can move."""
    names: list[str] = []
    if isinstance(step, (GoStep, MoveStep)):
        names.append(step.group)
    elif isinstance(step, GripperStep):
        names.append(step.group or gripper_group_of(model, step.arm or "") or "")
    elif isinstance(step, (PickStep, PlaceStep)):
        names += [step.arm, gripper_group_of(model, step.arm) or ""]
    elif isinstance(step, HandoffStep):
        for arm in (step.from_arm, step.to_arm):
            names += [arm, gripper_group_of(model, arm) or ""]
    for child in step.children:
        names += moved_groups(child, model)
    return [n for n in dict.fromkeys(names) if n in model.groups]


def load_and_check(path: str | Path, parameters: Mapping[str, object] | None = None,
                   *, policy: FolderPolicy | None = None, taught: TaughtPoses | None = None,
                   ) -> tuple[TaskSpec, Cell, list[Problem]]:
    """Load a task, load the cell it names and check its names against it.

    ``policy``: the folders the task and its cell may come from (None: anything loads);
    ``taught``: taught poses added to the cell's named poses (None: none).

    Raises:
        TaskSpecError: the task file is invalid.
        YamlError, RobotDescriptionError: the cell (or a robot of it) is invalid.
    """
    spec = load_task(path, parameters, policy=policy)
    cell = load_cell(spec.cell, policy=policy, taught=taught)
    return spec, cell, check_names(spec, cell)


def check_names(spec: TaskSpec, cell: Cell) -> list[Problem]:
    """Every name of ``spec`` that ``cell`` does not have, as problems (never raises)."""
    return _Checker(spec, cell).run()


class _Checker:
    def __init__(self, spec: TaskSpec, cell: Cell) -> None:
        self.spec, self.cell, self.model = spec, cell, cell.model
        self.problems: list[Problem] = []
        self.objects: dict[str, str] = {o.name: f"cell {cell.name!r}" for o in cell.objects}
        self.removed: dict[str, str] = {}

    def scene_file(self, path: Path) -> None:
        """The objects of the task's MoveIt scene file are known from the start."""
        from taskrunner.errors import InputError
        from taskrunner.moveit import load_planning_scene

        try:
            loaded = load_planning_scene(path, self.model)
        except InputError as exc:
            self.problems.append(Problem(exc.path, exc.line, exc.reason))
            return
        for name in loaded.object_names:
            self.objects[name] = f"scene file {path.name!r}"

    def run(self) -> list[Problem]:
        if self.spec.scene is not None:
            self.scene_file(self.spec.scene)
        for obj in self.spec.objects:
            self.add_object(obj)
        for step in self.spec.steps:
            self.step(step)
        if self.spec.expect is not None:
            self.expectation(self.spec.expect)
        self.expect_places(self.spec.steps, None)
        return self.problems

    def add(self, node: Node | None, field: str | None, message: str) -> None:
        loc = node.loc if node is not None else None
        if loc is None:
            self.problems.append(Problem(self.spec.path, None, message))
        else:
            self.problems.append(Problem(loc.file, loc.line_of(field) if field else loc.line,
                                         message))

    # ------------------------------------------------------------------- name lookups
    def group(self, node: Node, field: str, name: str) -> Group | None:
        group = self.model.groups.get(name)
        if group is None:
            self.add(node, field, f"group {name!r} is not a group of cell {self.cell.name!r}"
                     f"{did_you_mean(name, self.model.groups, 'groups')}")
        return group

    def arm(self, node: Node, field: str, name: str) -> Group | None:
        arms = arm_groups(self.model)
        if name in arms:
            return self.model.groups[name]
        if name in self.model.groups:
            listed = ", ".join(repr(a) for a in arms) or "none"
            self.add(node, field, f"group {name!r} is not an arm (a group with a tip link and an "
                     f"end effector); arms of cell {self.cell.name!r}: {listed}")
        else:
            self.add(node, field, f"arm {name!r} is not an arm of cell {self.cell.name!r}"
                     f"{did_you_mean(name, arms, 'arms')}")
        return None

    def named_pose(self, node: Node, field: str, group: Group, name: str) -> None:
        known = self.model.named_state_names(group.name)
        if name not in known:
            hint = did_you_mean(name, known, "named poses") if known else \
                f"; group {group.name!r} has no named poses"
            self.add(node, field, f"{name!r} is not a named pose of group {group.name!r}{hint}")

    def link(self, node: Node, field: str, name: str) -> None:
        if not self.model.has_link(name):
            self.add(node, field, f"link {name!r} is not a link of cell {self.cell.name!r}"
                     f"{did_you_mean(name, self.model.link_names, '')}")

    def frame(self, pose: PoseSpec | None, exclude: str | None = None) -> None:
        if pose is None or pose.frame == WORLD or self.model.has_link(pose.frame):
            return
        if pose.frame in self.objects and pose.frame != exclude:
            return
        known = [WORLD, *self.model.link_names, *(o for o in self.objects if o != exclude)]
        self.add(pose, "frame", f"frame {pose.frame!r} is not 'world', a link of cell "
                 f"{self.cell.name!r} or an object{did_you_mean(pose.frame, known, '')}")

    def target(self, step: Node, group: Group | None, pose: TargetPose | None,
               link: str | None, link_node: Node, link_field: str) -> None:
        if pose is not None:
            self.frame(pose)
        if link is not None:
            self.link(link_node, link_field, link)
        elif group is not None and group.tip_link is None:
            self.add(step, "group", f"group {group.name!r} has no tip link: say which 'link' "
                     "to move")

    def object(self, node: Node, field: str, name: str) -> None:
        if name in self.objects:
            return
        if name in self.removed:
            self.add(node, field, f"object {name!r} is not in the scene (removed at "
                     f"{self.removed[name]})")
        else:
            self.add(node, field, f"object {name!r} is not in the scene"
                     f"{did_you_mean(name, self.objects, 'objects')}")

    def add_object(self, obj: ObjectSpec) -> None:
        self.frame(obj.pose, exclude=obj.name)
        for link in obj.touch_links:
            self.link(obj, "touch_links", link)
        if obj.file is not None and "://" not in obj.file:
            problem = file_problem(obj.file)
            if problem is not None:
                self.add(obj, "file", f"mesh file not found: {obj.file_as_written}"
                         if problem == "file not found"
                         else f"mesh file {obj.file_as_written!r}: {problem}")
        first = self.objects.get(obj.name)
        if first is not None:
            self.add(obj, "name", f"object {obj.name!r} is already in the scene "
                     f"(declared at {first})" if not first.startswith("cell") else
                     f"object {obj.name!r} is already an object of {first}")
            return
        self.objects[obj.name] = str(obj.loc) if obj.loc else "(unknown)"
        self.removed.pop(obj.name, None)

    # -------------------------------------------------------------------------- steps
    def step(self, step: StepNode) -> None:
        handler = getattr(self, f"check_{step.verb}", None)
        if handler is not None:
            handler(step)
        for child in step.children:
            self.step(child)

    def check_go(self, step: GoStep) -> None:
        group = self.group(step, "group", step.group)
        if group is None:
            return
        if step.to is not None:
            self.named_pose(step, "to", group, step.to)
        for joint, value in (step.joints or {}).items():
            if joint not in group.joint_names:
                listed = ", ".join(repr(j) for j in group.joint_names)
                self.add(step, "joints", f"joint {joint!r} is not a joint of group "
                         f"{group.name!r} (its joints: {listed})")
                continue
            info = self.model.joint(joint)
            if not info.lower - 1e-9 <= value <= info.upper + 1e-9:
                self.add(step, "joints", f"joint {joint!r} = {value:g} is outside its limits "
                         f"[{info.lower:.4g}, {info.upper:.4g}]")
        if step.pose is not None:
            self.target(step, group, step.pose, step.pose.link, step.pose, "link")

    def check_move(self, step: MoveStep) -> None:
        group = self.group(step, "group", step.group)
        if step.pose is not None and step.pose.link is not None:
            self.target(step, group, step.pose, step.pose.link, step.pose, "link")
        else:
            self.target(step, group, step.pose, step.link, step, "link")

    def check_gripper(self, step: GripperStep) -> None:
        gripper = None
        if step.group is not None:
            gripper = self.group(step, "group", step.group)
        elif step.arm is not None and self.arm(step, "arm", step.arm) is not None:
            name = gripper_group_of(self.model, step.arm)
            if name is None:
                self.add(step, "arm", f"arm {step.arm!r} has no gripper group (no end effector "
                         "group with joints of its own); give the gripper 'group' instead")
            gripper = self.model.groups.get(name or "")
        if gripper is not None and step.to is not None:
            self.named_pose(step, "to", gripper, step.to)

    def check_pick(self, step: PickStep) -> None:
        self.arm(step, "arm", step.arm)
        self.object(step, "object", step.object)

    def check_place(self, step: PlaceStep) -> None:
        self.arm(step, "arm", step.arm)
        self.object(step, "object", step.object)
        self.frame(step.at, exclude=step.object)
        if step.on is not None:
            if step.on == step.object:
                self.add(step, "on", f"cannot place {step.object!r} on itself")
            else:
                self.object(step, "on", step.on)

    def check_handoff(self, step: HandoffStep) -> None:
        giver = self.arm(step, "from", step.from_arm)
        self.arm(step, "to", step.to_arm)
        self.object(step, "object", step.object)
        if step.from_arm == step.to_arm:
            self.add(step, "to", f"'handoff' needs two different arms (got {step.to_arm!r} for "
                     "both 'from' and 'to')")
        if isinstance(step.at, str):
            if giver is not None:
                self.named_pose(step, "at", giver, step.at)
        else:
            self.frame(step.at, exclude=step.object)

    def check_attach(self, step: AttachStep) -> None:
        self.object(step, "object", step.object)
        if step.arm is not None:
            self.arm(step, "arm", step.arm)
        if step.link is not None:
            self.link(step, "link", step.link)
        for link in step.touch_links:
            self.link(step, "touch_links", link)

    def check_detach(self, step: DetachStep) -> None:
        self.object(step, "object", step.object)

    def check_add_object(self, step: AddObjectStep) -> None:
        self.add_object(step.object)

    def check_remove_object(self, step: RemoveObjectStep) -> None:
        self.object(step, "object", step.object)
        if self.objects.pop(step.object, None) is not None:
            self.removed[step.object] = str(step.loc) if step.loc else "(unknown)"

    def check_parallel(self, step: ParallelStep) -> None:
        branches = [moved_groups(child, self.model) for child in step.steps]
        for j, later in enumerate(branches):
            for i, earlier in enumerate(branches[:j]):
                clash = _shared(self.model, earlier, later)
                if clash is None:
                    continue
                first, second = clash
                what = (f"both move group {first!r}" if first == second else
                        f"move groups {first!r} and {second!r}, which share joints")
                self.add(step.steps[j], None, f"branches {i + 1} and {j + 1} of 'parallel' "
                         f"{what}; parallel branches must move different arms")
                break


    # -------------------------------------------------------------------- expectations
    def check_expect(self, step: ExpectStep) -> None:
        self.expectation(step)

    def expectation(self, want: Expectation) -> None:
        """Names of an ``expect`` the cell or the scene (at that point) does not have."""
        for name, obj in want.objects.items():
            self.object(want, "objects", name)
            if obj.pose is not None:
                self.frame(obj.pose, exclude=name)
            if obj.held_by is not None and obj.held_by not in arm_groups(self.model) \
                    and not self.model.has_link(obj.held_by):
                known = [*arm_groups(self.model), *self.model.link_names]
                self.add(obj, "held_by", f"'held_by': {obj.held_by!r} is not an arm or a link "
                         f"of cell {self.cell.name!r}{did_you_mean(obj.held_by, known, '')}")
            if obj.on is not None:
                if obj.on == name:
                    self.add(obj, "on", f"'on': {name!r} cannot rest on itself")
                else:
                    self.object(obj, "on", obj.on)
        for name, group_want in want.groups.items():
            group = self.group(want, "groups", name)
            if group is None:
                continue
            if group_want.at is not None:
                self.named_pose(group_want, "at", group, group_want.at)
            for joint in group_want.joints or {}:
                if joint not in group.joint_names:
                    self.add(group_want, "joints", f"joint {joint!r} is not a joint of group "
                             f"{name!r}{did_you_mean(joint, group.joint_names, 'joints')}")

    def expect_places(self, steps: tuple[StepNode, ...], parent: StepNode | None) -> None:
        """An ``expect`` runs between steps: not in a ``parallel``, and with
        ``step_duration`` only after another step."""
        for i, step in enumerate(steps):
            if isinstance(step, ExpectStep):
                if isinstance(parent, ParallelStep):
                    self.add(step, None, "'expect' cannot run in a 'parallel' (it would check "
                             "while the other branches move): put it after the 'parallel'")
                elif step.step_duration is not None and i == 0:
                    self.add(step, "step_duration", "'step_duration' needs a step before "
                             "this 'expect' in the same list")
            self.expect_places(step.children, step)


def _shared(model: RobotModel, first: Iterable[str],
            second: Iterable[str]) -> tuple[str, str] | None:
    """A pair of groups, one of each list, that share a joint."""
    for a in first:
        for b in second:
            if set(model.groups[a].joint_names) & set(model.groups[b].joint_names):
                return a, b
    return None
