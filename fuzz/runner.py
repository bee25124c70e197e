"""Run generated inputs in worker processes with a time limit each, classify the outcomes, print the table.

Outcomes: ``ok`` (a result that passes :mod:`fuzz.checks`), ``typed`` (an ``IncirCuError``), ``type error``
(a ``TypeError`` on plain type misuse), ``untyped`` (any other exception), ``hang`` (over the time limit; the
worker is killed and replaced), ``invalid`` (a result that fails the checks) and ``crash`` (the worker died).
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

OUTCOMES = ("ok", "typed", "type error", "untyped", "hang", "invalid", "crash")
FAILURES = ("untyped", "hang", "invalid", "crash")


def run_case(seed, index, small):
    """Generate and run one input; return ``(category, outcome, detail, seconds)``."""
    from incircu_plugin.core import IncirCuError

    from .checks import problems
    from .inputs import call, make_case

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = make_case(seed, index, small)
    started = time.perf_counter()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = call(case)
    except IncirCuError as error:
        return case.category, "typed", f"{type(error).__name__}: {error}", time.perf_counter() - started
    except TypeError as error:
        return case.category, "type error", str(error), time.perf_counter() - started
    except Exception as error:  # noqa: BLE001 - an untyped exception is what the campaign looks for
        where = traceback.extract_tb(error.__traceback__)[-1]
        detail = f"{type(error).__name__}: {error} ({Path(where.filename).name}:{where.lineno} {where.name})"
        return case.category, "untyped", detail, time.perf_counter() - started
    seconds = time.perf_counter() - started
    found = problems(case, result)
    return case.category, "invalid" if found else "ok", "; ".join(found), seconds


def _worker(connection, seed, small):
    while True:
        index = connection.recv()
        if index is None:
            return
        connection.send((index, run_case(seed, index, small)))


class Pool:
    """Worker processes fed one input at a time, so a hanging input can be killed alone."""

    def __init__(self, workers, seed, small, time_limit):
        self.context = multiprocessing.get_context("fork")
        self.seed, self.small, self.time_limit = seed, small, time_limit
        self.workers = [self._start() for _ in range(workers)]

    def _start(self):
        parent, child = self.context.Pipe()
        process = self.context.Process(target=_worker, args=(child, self.seed, self.small), daemon=True)
        process.start()
        child.close()
        return {"process": process, "connection": parent, "index": None, "deadline": None}

    def run(self, indices, report):
        """Run every index; call ``report(index, (category, outcome, detail, seconds))`` for each."""
        pending = list(reversed(list(indices)))
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
                        index, outcome = worker["connection"].recv()
                    except (EOFError, OSError):
                        worker["process"].join(timeout=1)
                        report(worker["index"], (None, "crash", f"exit code {worker['process'].exitcode}", None))
                        self._replace(slot)
                        continue
                    worker["index"] = None
                    report(index, outcome)
                elif time.monotonic() >= worker["deadline"]:
                    report(worker["index"], (None, "hang", f"over {self.time_limit:g} s", self.time_limit))
                    self._replace(slot)

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


def campaign(count, seed, small=False, workers=2, time_limit=10.0, start=0, progress=None):
    """Run inputs ``start .. start + count - 1``.

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

    pool = Pool(workers, seed, small, time_limit)
    try:
        pool.run(range(start, start + count), report)
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


def show_case(seed, index, small):
    """Print one input and run it here (a reproducer)."""
    from .inputs import make_case

    case = make_case(seed, index, small)
    print(f"# seed {seed}, index {index}{' (small)' if small else ''}: {case.category}")
    print(case.describe(limit=100_000))
    print(run_case(seed, index, small))


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m fuzz", description=__doc__.splitlines()[0])
    parser.add_argument("--count", "-n", type=int, default=2000, help="number of inputs")
    parser.add_argument("--seed", type=int, default=20261201)
    parser.add_argument("--start", type=int, default=0, help="first input index")
    parser.add_argument("--small", action="store_true", help="short channels and milder thin boxes (test sample)")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--time-limit", type=float, default=10.0, help="seconds per input")
    parser.add_argument("--case", type=int, help="print and run this one input in this process")
    parser.add_argument("--failures", type=Path, help="write the failures as JSON lines here")
    arguments = parser.parse_args(argv)
    if arguments.case is not None:
        show_case(arguments.seed, arguments.case, arguments.small)
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
    )
    elapsed = time.perf_counter() - started
    print(
        f"{arguments.count} inputs, seed {arguments.seed}{', small' if arguments.small else ''}, "
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
