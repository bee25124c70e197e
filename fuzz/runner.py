"""Run generated inputs in worker processes with a time limit each, classify the outcomes, print the table.

Outcomes: ``ok`` (a result that passes :mod:`fuzz.checks`), ``typed`` (an ``IncirCuError``), ``type error``
(a ``TypeError`` on plain type misuse), ``untyped`` (any other exception), ``hang`` (over the time limit; the
worker is killed and replaced), ``invalid`` (a result that fails the checks) and ``crash`` (the worker died).

With ``--together K`` the inputs are also run as a layer is: each run of ``K`` consecutive inputs traced together
in one batch (``run_many_steps`` on their step generators, what an array of geometries runs). An input whose outcome alone is ``ok``, ``typed``
or ``type error`` but differs in the batch (:func:`fuzz.checks.together_problems`) is ``batch differs``.
"""

import argparse
import json
import multiprocessing
import sys
import time
import traceback
import warnings
from collections import Counter, defaultdict
from multiprocessing.connection import wait
from pathlib import Path

OUTCOMES = ("ok", "typed", "type error", "untyped", "hang", "invalid", "crash", "batch differs")
FAILURES = ("untyped", "hang", "invalid", "crash", "batch differs")


def _quietly(function, *args):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return function(*args)


def run_case(seed, index, small, oracle=False):
    """Generate and run one input; return ``(category, outcome, detail, seconds)``."""
    from .inputs import make_case

    case = _quietly(make_case, seed, index, small)
    return _run(case, oracle)[0]


def _run(case, oracle=False):
    """Run one input alone: ``((category, outcome, detail, seconds), value)``, the value being what the call
    returned or raised; with ``oracle``, a result is also checked against the exact axis."""
    from incircu_plugin.core import IncirCuError

    from .checks import oracle_problems, problems
    from .inputs import call

    started = time.perf_counter()
    try:
        result = _quietly(call, case)
    except IncirCuError as error:
        return (case.category, "typed", f"{type(error).__name__}: {error}", time.perf_counter() - started), error
    except TypeError as error:
        return (case.category, "type error", str(error), time.perf_counter() - started), error
    except Exception as error:  # noqa: BLE001 - an untyped exception is what the campaign looks for
        where = traceback.extract_tb(error.__traceback__)[-1]
        detail = f"{type(error).__name__}: {error} ({Path(where.filename).name}:{where.lineno} {where.name})"
        return (case.category, "untyped", detail, time.perf_counter() - started), error
    seconds = time.perf_counter() - started
    found = problems(case, result)
    if oracle and not found:
        found = oracle_problems(case, result)
    return (case.category, "invalid" if found else "ok", "; ".join(found), seconds), result


def run_batch(seed, first, size, small, oracle=False):
    """Run inputs ``first .. first + size - 1`` alone, then those with a step form together in one batch.

    Returns ``[(index, (category, outcome, detail, seconds)), ...]``: each input's outcome alone, or ``batch
    differs`` where it was ``ok``, ``typed`` or ``type error`` alone and the batch gives something else.
    """
    from incircu_plugin.core._many import run_many_steps

    from .checks import together_problems
    from .inputs import make_case, steps

    cases = [_quietly(make_case, seed, index, small) for index in range(first, first + size)]
    runs = [_run(case, oracle) for case in cases]
    outcomes = [outcome for outcome, _ in runs]
    generators, members = [], []
    for position, case in enumerate(cases):
        try:
            generator = steps(case)
        except TypeError as error:
            # Bound at the call, like the plain function: the batch sees the same error.
            members.append((position, error))
            continue
        if generator is not None:
            generators.append(generator)
            members.append((position, None))
    started = time.perf_counter()
    together = iter(_quietly(run_many_steps, generators))
    seconds = time.perf_counter() - started
    for position, bound_error in members:
        category, kind, _, _ = outcomes[position]
        value = bound_error if bound_error is not None else next(together)
        if kind not in ("ok", "typed", "type error"):
            continue
        found = together_problems(cases[position], value, runs[position][1])
        if found:
            outcomes[position] = (category, "batch differs", "; ".join(found), seconds)
    return list(zip(range(first, first + size), outcomes))


def run_unit(seed, first, size, small, oracle=False):
    """Run one unit of work (one input, or a batch of ``size`` when ``size > 1``):
    ``[(index, (category, outcome, detail, seconds)), ...]``."""
    if size == 1:
        return [(first, run_case(seed, first, small, oracle))]
    return run_batch(seed, first, size, small, oracle)


def _worker(connection, seed, small, size, oracle):
    while True:
        first = connection.recv()
        if first is None:
            return
        connection.send((first, run_unit(seed, first, size, small, oracle)))


class Pool:
    """Worker processes fed one unit at a time (an input, or a batch of ``size`` inputs), so a hanging unit can
    be killed alone; its time limit is ``time_limit`` per input."""

    def __init__(self, workers, seed, small, time_limit, size=1, oracle=False):
        self.context = multiprocessing.get_context("fork")
        self.seed, self.small, self.size, self.time_limit = seed, small, size, time_limit * size
        self.oracle = oracle
        self.workers = [self._start() for _ in range(workers)]

    def _start(self):
        parent, child = self.context.Pipe()
        arguments = (child, self.seed, self.small, self.size, self.oracle)
        process = self.context.Process(target=_worker, args=arguments, daemon=True)
        process.start()
        child.close()
        return {"process": process, "connection": parent, "index": None, "deadline": None}

    def run(self, firsts, report):
        """Run the unit starting at every index of ``firsts``; call ``report(index, (category, outcome, detail,
        seconds))`` for each input of each."""
        pending = list(reversed(list(firsts)))
        while pending or any(w["index"] is not None for w in self.workers):
            for slot, worker in enumerate(self.workers):
                if worker["index"] is None and pending:
                    worker["index"] = pending.pop()
                    worker["deadline"] = time.monotonic() + self.time_limit
                    worker["connection"].send(worker["index"])
            busy = [w for w in self.workers if w["index"] is not None]
            timeout = max(0.0, min(w["deadline"] for w in busy) - time.monotonic())
            ready = wait([w["connection"] for w in busy], timeout=timeout)
            for slot, worker in enumerate(self.workers):
                if worker["index"] is None:
                    continue
                if worker["connection"] in ready:
                    try:
                        _, outcomes = worker["connection"].recv()
                    except (EOFError, OSError):
                        worker["process"].join(timeout=1)
                        self._report_unit(worker["index"], "crash", f"exit code {worker['process'].exitcode}", report)
                        self._replace(slot)
                        continue
                    worker["index"] = None
                    for index, outcome in outcomes:
                        report(index, outcome)
                elif time.monotonic() >= worker["deadline"]:
                    self._report_unit(worker["index"], "hang", f"over {self.time_limit:g} s", report)
                    self._replace(slot)

    def _report_unit(self, first, kind, detail, report):
        """Report every input of the unit starting at ``first`` as ``kind`` (a crash or a hang of its worker)."""
        for index in range(first, first + self.size):
            report(index, (None, kind, detail, self.time_limit if kind == "hang" else None))

    def _replace(self, slot):
        old = self.workers[slot]
        old["process"].kill()
        old["process"].join()
        old["connection"].close()
        self.workers[slot] = self._start()

    def close(self):
        for worker in self.workers:
            try:
                worker["connection"].send(None)
            except OSError:
                pass
            worker["process"].join(timeout=5)
            if worker["process"].is_alive():
                worker["process"].kill()


def campaign(count, seed, small=False, workers=2, time_limit=10.0, start=0, progress=None, together=1, oracle=False):
    """Run inputs ``start .. start + count - 1`` (with ``together > 1``: in batches of that many, each input also
    traced together with the others of its batch, see :func:`run_batch`; ``count`` is rounded up to whole
    batches; with ``oracle``, results are also checked against the exact axis, :func:`fuzz.checks.oracle_problems`).

    Returns
    -------
    counts : dict of Counter
        Category -> outcome -> number of inputs.
    failures : list of dict
        ``seed``, ``index``, ``category``, ``outcome``, ``detail`` of every failing input.
    typed : dict of Counter
        Category -> error class -> number of typed errors.
    """
    from .inputs import make_case

    counts = defaultdict(Counter)
    failures = []
    typed = defaultdict(Counter)

    def report(index, outcome):
        category, kind, detail, _ = outcome
        if category is None:
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    category = make_case(seed, index, small).category
            except Exception as error:  # noqa: BLE001 - a generator bug is reported, not fatal
                category = f"generator error ({type(error).__name__})"
        counts[category][kind] += 1
        if kind == "typed":
            typed[category][detail.split(":")[0]] += 1
        if kind in FAILURES:
            failures.append({"seed": seed, "index": index, "category": category, "outcome": kind, "detail": detail})
        if progress and sum(sum(c.values()) for c in counts.values()) % progress == 0:
            print(f"  {sum(sum(c.values()) for c in counts.values())} inputs done", file=sys.stderr, flush=True)

    pool = Pool(workers, seed, small, time_limit, together, oracle)
    try:
        pool.run(range(start, start + count, together), report)
    finally:
        pool.close()
    return counts, failures, typed


def table(counts):
    """The outcome table as Markdown: one row per category, plus the total."""
    header = "| category | inputs | " + " | ".join(OUTCOMES) + " |"
    lines = [header, "|---|" + "---:|" * (len(OUTCOMES) + 1)]
    total = Counter()
    for category in sorted(counts):
        row = counts[category]
        total.update(row)
        lines.append(f"| {category} | {sum(row.values())} | " + " | ".join(str(row[o]) for o in OUTCOMES) + " |")
    lines.append(f"| **all** | **{sum(total.values())}** | " + " | ".join(f"**{total[o]}**" for o in OUTCOMES) + " |")
    return "\n".join(lines)


def show_case(seed, index, small, together=1, start=0, oracle=False):
    """Print one input and run it here (a reproducer): alone, or in its batch of ``together`` inputs (the
    batches of a campaign from ``start``)."""
    from .inputs import make_case

    case = make_case(seed, index, small)
    print(f"# seed {seed}, index {index}{' (small)' if small else ''}: {case.category}")
    print(case.describe(limit=100_000))
    if together == 1:
        print(run_case(seed, index, small, oracle))
        return
    first = index - (index - start) % together
    print(f"# in the batch of inputs {first} to {first + together - 1}")
    print(dict(run_batch(seed, first, together, small, oracle))[index])


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m fuzz", description=__doc__.splitlines()[0])
    parser.add_argument("--count", "-n", type=int, default=2000, help="number of inputs")
    parser.add_argument("--seed", type=int, default=20261201)
    parser.add_argument("--start", type=int, default=0, help="first input index")
    parser.add_argument("--small", action="store_true", help="short channels and milder thin boxes (test sample)")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--time-limit", type=float, default=10.0, help="seconds per input")
    parser.add_argument(
        "--together", type=int, default=1, metavar="K", help="also trace each run of K inputs together in one batch"
    )
    parser.add_argument(
        "--oracle", action="store_true", help="also check each polygon's line against the exact medial axis (slower)"
    )
    parser.add_argument(
        "--case", type=int, help="print and run this one input in this process (with --together K: its batch)"
    )
    parser.add_argument("--failures", type=Path, help="write the failures as JSON lines here")
    arguments = parser.parse_args(argv)
    if arguments.case is not None:
        show_case(
            arguments.seed, arguments.case, arguments.small, arguments.together, arguments.start, arguments.oracle
        )
        return 0
    started = time.perf_counter()
    counts, failures, typed = campaign(
        arguments.count,
        arguments.seed,
        arguments.small,
        arguments.workers,
        arguments.time_limit,
        arguments.start,
        progress=max(1000, arguments.count // 20),
        together=arguments.together,
        oracle=arguments.oracle,
    )
    elapsed = time.perf_counter() - started
    batches = f", in batches of {arguments.together}" if arguments.together > 1 else ""
    batches += ", against the oracle" if arguments.oracle else ""
    print(
        f"{sum(sum(row.values()) for row in counts.values())} inputs, seed {arguments.seed}"
        f"{', small' if arguments.small else ''}{batches}, "
        f"{arguments.workers} workers, {arguments.time_limit:g} s limit, {elapsed:.0f} s, "
        f"{time.strftime('%Y-%m-%d')}\n"
    )
    print(table(counts))
    print("\nTyped errors by class:")
    for category in sorted(typed):
        print(f"  {category}: " + ", ".join(f"{name} {n}" for name, n in typed[category].most_common()))
    if arguments.failures:
        arguments.failures.parent.mkdir(parents=True, exist_ok=True)
        arguments.failures.write_text("".join(json.dumps(f) + "\n" for f in failures))
    if failures:
        print(
            "\nFailures (rerun one with: python -m fuzz --seed S --case I"
            + (" --small" if arguments.small else "")
            + (f" --together {arguments.together} --start {arguments.start}" if arguments.together > 1 else "")
            + (" --oracle" if arguments.oracle else "")
            + "):"
        )
        shown = Counter()
        for failure in failures:
            key = (failure["category"], failure["outcome"])
            shown[key] += 1
            if shown[key] <= 3:
                print(
                    f"  {failure['outcome']:8} {failure['category']}: --seed {failure['seed']} --case "
                    f"{failure['index']}: {failure['detail'][:300]}"
                )
    return 1 if failures else 0
