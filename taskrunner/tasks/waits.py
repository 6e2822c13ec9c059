"""``wait_for`` between the branches of a ``parallel``: which step waits for which.

A step in a branch of a ``parallel`` may say ``wait_for: {step: NAME}``: it starts when
the step of that ``name`` in *another branch of the same parallel* has finished (the
right arm starts stacking when the left arm has put the base down), or, with ``until:``,
when that step has reached a moment within it (:data:`~taskrunner.tasks.steps.MOMENTS`:
a ``place``'s ``released``, the base let go before its arm retreats). A moment the
named step does not have is refused here too. The loader checks
every ``wait_for`` here (:func:`wait_problems`): the name is given to exactly one step,
the two steps are in different branches of a ``parallel`` around both (steps of one
sequence already run in order), and no set of waits can hold every step back (a cycle,
counting the order of each sequence too: ``a`` waits for ``d`` while ``d`` comes after
``c`` which waits for ``b``, after ``a``). :func:`wait_pairs` gives the pairs a compiler
and a check follow.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass

from taskrunner.errors import did_you_mean
from taskrunner.tasks.problem import Problem
from taskrunner.tasks.steps import MOMENTS, ParallelStep, StepNode

__all__ = ["FINISHED", "WaitPair", "named_steps", "wait_pairs", "wait_problems"]

@dataclass(frozen=True)
class WaitPair:
    """A resolved ``wait_for``: ``waiter`` starts when ``named`` has finished; both are
    in branches ``waiter_branch`` and ``named_branch`` of ``parallel``."""

    waiter: StepNode
    named: StepNode
    parallel: ParallelStep
    waiter_branch: int
    named_branch: int

    @property
    def name(self) -> str:
        return str(getattr(self.named, "name", ""))

    @property
    def moment(self) -> str:
        """The moment of ``named`` waited for: ``finished`` or one of :data:`MOMENTS`."""
        wait_for = getattr(self.waiter, "wait_for", None)
        return str(getattr(wait_for, "until", FINISHED))


FINISHED = "finished"
"""The moment a ``wait_for`` waits for by default: the whole named step has finished."""


def _walk(steps: Sequence[StepNode], path: tuple[tuple[StepNode | None, int], ...] = (),
          parent: StepNode | None = None
          ) -> Iterator[tuple[StepNode, tuple[tuple[StepNode | None, int], ...]]]:
    for i, step in enumerate(steps):
        here = path + ((parent, i),)
        yield step, here
        yield from _walk(step.children, here, step)


def named_steps(steps: Sequence[StepNode]) -> dict[str, list[StepNode]]:
    """The steps with a ``name`` (a label a ``wait_for`` can name), by name."""
    out: dict[str, list[StepNode]] = {}
    for step, _ in _walk(steps):
        name = getattr(step, "name", None)
        if isinstance(name, str) and "wait_for" in type(step).model_fields:
            out.setdefault(name, []).append(step)
    return out


def _line(step: StepNode, field: str | None = None) -> str:
    loc = step.loc
    if loc is None:
        return "?"
    line = loc.line_of(field) if field else loc.line
    return f"line {line}" if line is not None else str(loc.file)


def _resolve(steps: Sequence[StepNode]) -> tuple[list[WaitPair], list[Problem]]:
    places = {id(step): path for step, path in _walk(steps)}
    named = named_steps(steps)
    pairs: list[WaitPair] = []
    problems: list[Problem] = []
    for step, path in _walk(steps):
        wait_for = getattr(step, "wait_for", None)
        if wait_for is None:
            continue
        loc = step.loc
        where = (loc.file if loc else None, loc.line_of("wait_for") if loc else None)

        def refuse(message: str) -> None:
            problems.append(Problem(where[0], where[1], f"'wait_for': {message}"))

        found = named.get(wait_for.step, [])
        if not any(isinstance(p, ParallelStep) for p, _ in path):
            refuse("only a step in a branch of a 'parallel' can wait for another branch's "
                   "step (steps of one sequence run in order already)")
            continue
        if not found:
            refuse(f"no step is named {wait_for.step!r}"
                   f"{did_you_mean(wait_for.step, named, 'named steps')}")
            continue
        if len(found) > 1:
            lines = ", ".join(_line(s) for s in found)
            refuse(f"{len(found)} steps are named {wait_for.step!r} ({lines}): give the one "
                   "to wait for a name of its own")
            continue
        other = found[0]
        there = places[id(other)]
        common = 0
        while common < min(len(path), len(there)) and _same(path[common], there[common]):
            common += 1
        if other is step or common == len(path) or common == len(there):
            refuse(f"{wait_for.step!r} ({_line(other)}) is this step or one around or inside "
                   "it; a step waits for a step of another branch of a 'parallel'")
            continue
        parent = path[common][0]
        if not isinstance(parent, ParallelStep):
            refuse(f"{wait_for.step!r} ({_line(other)}) is not in another branch of a "
                   "'parallel' around this step (steps of one sequence run in order already)")
            continue
        moment = wait_for.until
        if moment != FINISHED and moment not in MOMENTS.get(other.verb, ()):
            has = MOMENTS.get(other.verb, ())
            refuse(f"step {wait_for.step!r} ({_line(other)}) is a '{other.verb}', which has no "
                   f"moment {moment!r} (it has: "
                   f"{', '.join(repr(m) for m in (FINISHED, *has))})")
            continue
        pairs.append(WaitPair(step, other, parent, path[common][1], there[common][1]))
    return pairs, problems


def _same(a: tuple[StepNode | None, int], b: tuple[StepNode | None, int]) -> bool:
    return a[0] is b[0] and a[1] == b[1]


def wait_pairs(steps: Sequence[StepNode]) -> list[WaitPair]:
    """Every valid ``wait_for`` of ``steps`` and what it waits for (the invalid ones are
    left out: :func:`wait_problems` reports them)."""
    return _resolve(steps)[0]


def wait_problems(steps: Sequence[StepNode]) -> list[Problem]:
    """What is wrong with the ``wait_for`` of ``steps`` (module text), at the lines of the
    ``wait_for`` fields; empty when every one can be followed."""
    pairs, problems = _resolve(steps)
    if pairs and not problems:
        cycle = _cycle(steps, pairs)
        if cycle:
            first = cycle[0].waiter.loc
            chain = "; ".join(f"{_line(p.waiter, 'wait_for')} waits for {p.name!r} "
                              f"({_line(p.named)})" for p in cycle)
            problems.append(Problem(first.file if first else None,
                                    first.line_of("wait_for") if first else None,
                                    f"'wait_for': these steps wait for each other, so none "
                                    f"can start (a cycle): {chain}"))
    return problems


_Event = tuple[str, int]  # ("s" start | "f" finish, id of the step)


def _cycle(steps: Sequence[StepNode], pairs: list[WaitPair]) -> list[WaitPair]:
    """The waits of a cycle of "cannot start before" (the order of every sequence, a
    composite around its children, and the waits), in order; empty: none."""
    edges: dict[_Event, list[_Event]] = {}

    def edge(a: _Event, b: _Event) -> None:
        edges.setdefault(a, []).append(b)

    def order(parent: _Event, children: Sequence[StepNode], end: _Event, chain: bool) -> None:
        previous = parent
        for child in children:
            edge(previous if chain else parent, ("s", id(child)))
            if not chain:
                edge(("f", id(child)), end)
            previous = ("f", id(child))
            edge(("s", id(child)), ("f", id(child)))
            order(("s", id(child)), child.children, ("f", id(child)),
                  not isinstance(child, ParallelStep))
        if chain:
            edge(previous, end)

    order(("s", 0), steps, ("f", 0), True)
    by_edge: dict[tuple[_Event, _Event], WaitPair] = {}
    for pair in pairs:
        a, b = ("f", id(pair.named)), ("s", id(pair.waiter))
        edge(a, b)
        by_edge[(a, b)] = pair
    # Depth-first search for a back edge (iterative: deep task trees stay in bounds).
    state: dict[_Event, int] = {}
    for root in list(edges):
        if state.get(root):
            continue
        stack: list[tuple[_Event, Iterator[_Event]]] = [(root, iter(edges.get(root, ())))]
        state[root] = 1
        trail = [root]
        while stack:
            node, successors = stack[-1]
            nxt = next(successors, None)
            if nxt is None:
                stack.pop()
                trail.pop()
                state[node] = 2
                continue
            if state.get(nxt) == 1:
                loop = trail[trail.index(nxt):] + [nxt]
                return [by_edge[e] for e in zip(loop, loop[1:]) if e in by_edge]
            if not state.get(nxt):
                state[nxt] = 1
                trail.append(nxt)
                stack.append((nxt, iter(edges.get(nxt, ()))))
    return []
