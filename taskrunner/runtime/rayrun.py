"""Running test and sweep cases on a Ray cluster (``--ray [ADDRESS]``; the ``ray`` extra).

Each case is one Ray task running :func:`taskrunner.runtime.testing.run_case` (or the
given ``work``) in a Ray worker; its :class:`~taskrunner.runtime.testing.CaseResult`
comes back to the caller. A worker that dies is retried once by Ray (``max_retries=1``)
— Ray does not say whether it did, so a case that came back is reported with the
attempt it knows (1) — and a second death becomes an ``error`` result naming Ray's
error. The workers need taskrunner installed (same version) and the task files at the
same paths: on one machine they are; on a cluster, use a shared folder or Ray's
``runtime_env``.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from taskrunner.errors import InputError
from taskrunner.runtime.testing import Case, CaseResult

__all__ = ["run_on_ray"]


def _ray():  # type: ignore[no-untyped-def]
    try:
        import ray
    except ImportError:
        raise InputError("--ray needs Ray: pip install 'ray[default]>=2.40,<3'") from None
    return ray


def run_on_ray(cases: Sequence[Case], address: str,
               on_result: Callable[[CaseResult], object] | None,
               work: Callable[[Case], CaseResult]) -> list[CaseResult]:
    """Run ``cases`` as Ray tasks; results in the order of ``cases``.

    Args:
        address: ``"local"`` (start Ray here, unless it is running in this process
            already), ``"auto"`` (a running cluster on this machine) or a cluster address.
    """
    ray = _ray()
    started_here = False
    if not ray.is_initialized():
        ray.init(address=None if address == "local" else address,
                 include_dashboard=False, log_to_driver=False)
        started_here = True
    try:
        remote = ray.remote(max_retries=1, retry_exceptions=False)(work)
        refs = [remote.remote(case) for case in cases]
        index = {ref: i for i, ref in enumerate(refs)}
        results: dict[int, CaseResult] = {}
        pending = list(refs)
        while pending:
            ready, pending = ray.wait(pending, num_returns=1)
            for ref in ready:
                i = index[ref]
                try:
                    result = ray.get(ref)
                except ray.exceptions.RayError as exc:
                    first = str(exc).strip().splitlines()[0] if str(exc).strip() else ""
                    result = CaseResult(cases[i], "error", None, 0.0,
                                        f"the Ray worker running it failed twice "
                                        f"({type(exc).__name__}: {first})", attempts=2)
                results[i] = result
                if on_result is not None:
                    on_result(result)
        return [results[i] for i in range(len(cases))]
    finally:
        if started_here:
            ray.shutdown()
