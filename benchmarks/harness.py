"""Run one tool on one case in a clean child process, with a time limit, and measure it.

A child per (tool, case) keeps a runaway peer from stalling the whole benchmark: past
``timeout_seconds`` it is killed, with every process it started, and reported as such. Children are forked
from a *fork server* (:mod:`multiprocessing`'s ``forkserver``) that imported every tool library once and
holds nothing else: no run pays for an import, and none runs in a copy of this process's heap (the cases,
their oracles, earlier results), which made geometry creation in a child up to twice as slow (copy-on-write
of the parent's pages). A child receives a copy of the case without its reference callables
(:func:`portable`) and sends back the tool's output as WKB; the parent measures it against the reference.
"""

import multiprocessing
import os
import resource
import signal
import time
import traceback
from dataclasses import replace

import shapely
from metrics import Measurement, measure, time_call

#: Address space a benchmark child may add to what it inherits (bytes): a runaway tool stops with a
#: MemoryError instead of pushing the shared machine into the OOM killer.
CHILD_MEMORY_BYTES = 6 * 2**30

#: Modules the fork server imports before forking any child (a missing optional peer is skipped).
PRELOADED = ("centerline.geometry", "label_centerlines", "pygeoops", "pysfcgal.geometry", "incircu_plugin.core")

_context = None


def limit_memory(extra_bytes=CHILD_MEMORY_BYTES):
    """Cap this process's address space at its current size plus ``extra_bytes`` (Linux)."""
    with open("/proc/self/status") as status:
        current = next(int(line.split()[1]) * 1024 for line in status if line.startswith("VmSize"))
    resource.setrlimit(resource.RLIMIT_AS, (current + extra_bytes, current + extra_bytes))


def preload():
    """Start the fork server, which imports every tool library once, so children start warm and clean."""
    global _context
    if _context is None:
        _context = multiprocessing.get_context("forkserver")
        _context.set_forkserver_preload(["__main__", *PRELOADED])
    return _context


def portable(case):
    """``case`` without its reference callables (an oracle cannot be pickled): all a tool needs to run."""
    extra = {key: value for key, value in case.extra.items() if not callable(value)}
    return replace(case, axis_distance=None, extra=extra)


def _error_text(error):
    """One line, at most 160 characters, naming ``error``."""
    return f"{type(error).__name__}: {error}".splitlines()[0][:160]


def _child(connection, tool, case, budget_seconds):
    os.setpgrp()  # its own process group, so a timeout also kills what it started (qgis_process, GRASS)
    if not tool.external:
        limit_memory()
    try:
        geometry, seconds, runs = time_call(tool.run, case, budget_seconds=budget_seconds)
        wkb = None if geometry is None else shapely.to_wkb(geometry)
        connection.send((wkb, seconds, runs, ""))
    except Exception as error:  # noqa: BLE001 (a peer failing on an input is a result, not a crash)
        connection.send((None, None, 0, _error_text(error)))
        traceback.print_exc()
    finally:
        connection.close()


def _start(target, *arguments):
    """Start ``target(sender, *arguments)`` in a child of the fork server; return (process, receiver)."""
    context = preload()
    receiver, sender = context.Pipe(duplex=False)
    process = context.Process(target=target, args=(sender, *arguments))
    process.start()
    sender.close()
    return process, receiver


def _kill(process):
    """Kill ``process`` and everything it started (its process group)."""
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def run_tool(tool, case, timeout_seconds=90.0, budget_seconds=2.0):
    """Measure ``tool`` on ``case``; returns (Measurement, geometry or None).

    The geometry comes back only when ``case.extra["keep_geometry"]`` is true (for the plots).
    """
    process, receiver = _start(_child, tool, portable(case), budget_seconds)
    if not receiver.poll(timeout_seconds):
        _kill(process)
        process.join()
        return Measurement(tool.name, case.name, None, 0, error=f"timeout > {timeout_seconds:.0f} s"), None
    try:
        wkb, seconds, runs, error = receiver.recv()
    except EOFError:
        wkb, seconds, runs, error = None, None, 0, "child died"
    process.join()
    if error:
        return Measurement(tool.name, case.name, None, 0, error=error), None
    geometry = None if wkb is None else shapely.from_wkb(wkb)
    measurement = measure(tool.name, case, geometry, seconds, runs)
    return measurement, geometry if case.extra.get("keep_geometry") and not measurement.error else None


def _layer_child(connection, tool, cases):
    os.setpgrp()
    if not tool.external:
        limit_memory()
    if tool.run_all is not None:
        _send_whole_layer(connection, tool, cases)
        return
    for index, case in enumerate(cases):
        started = time.perf_counter()
        try:
            geometry = tool.run(case)
            seconds = time.perf_counter() - started
            wkb = None if geometry is None else shapely.to_wkb(geometry)
            connection.send((index, seconds, wkb, "" if wkb else "no output"))
        except Exception as error:  # noqa: BLE001 (a peer failing on a polygon is a result, not a crash)
            connection.send((index, time.perf_counter() - started, None, _error_text(error)))
    connection.send(None)
    connection.close()


def _send_whole_layer(connection, tool, cases):
    """Run ``tool.run_all`` on all cases in one call; send each case's outcome with an equal share of its time."""
    started = time.perf_counter()
    try:
        outcomes = tool.run_all(cases)
    except Exception as error:  # noqa: BLE001 (a tool failing on the layer is a result, not a crash)
        outcomes = [error] * len(cases)
    share = (time.perf_counter() - started) / max(len(cases), 1)
    for index, outcome in enumerate(outcomes):
        if isinstance(outcome, Exception):
            connection.send((index, share, None, _error_text(outcome)))
        else:
            connection.send((index, share, None if outcome is None else shapely.to_wkb(outcome), ""))
    connection.send(None)
    connection.close()


def run_layer(tool, cases, timeout_seconds):
    """Run ``tool`` on every case in turn in one child, killed past ``timeout_seconds`` in all.

    Returns
    -------
    results : list of (seconds, geometry or None, error) or None
        One entry per case; None for the cases not reached before the time limit. ``seconds`` is the
        tool call alone (no transfer).
    note : str
        Empty, or why the run stopped early (time limit, child died).
    """
    process, receiver = _start(_layer_child, tool, [portable(case) for case in cases])
    deadline = time.monotonic() + timeout_seconds
    results, note = [None] * len(cases), ""
    while True:
        remaining = deadline - time.monotonic()
        if remaining <= 0 or not receiver.poll(remaining):
            note = f"timeout > {timeout_seconds:.0f} s"
            break
        try:
            message = receiver.recv()
        except EOFError:
            note = "child died"
            break
        if message is None:
            break
        index, seconds, wkb, error = message
        results[index] = (seconds, None if wkb is None else shapely.from_wkb(wkb), error)
    if note:
        _kill(process)
    process.join()
    return results, note
