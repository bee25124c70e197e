"""Run one tool on one case in a forked child process, with a time limit, and measure it.

A child per (tool, case) keeps a runaway peer from stalling the whole benchmark: past
``timeout_seconds`` it is killed, with every process it started, and reported as such. The parent imports every tool module before
forking, so no run pays for an import.
"""

import multiprocessing
import os
import resource
import signal
import time
import traceback

import shapely
from metrics import Measurement, measure, time_call

#: Address space a benchmark child may add to what it inherits (bytes): a runaway tool stops with a
#: MemoryError instead of pushing the shared machine into the OOM killer.
CHILD_MEMORY_BYTES = 6 * 2**30


def limit_memory(extra_bytes=CHILD_MEMORY_BYTES):
    """Cap this process's address space at its current size plus ``extra_bytes`` (Linux)."""
    with open("/proc/self/status") as status:
        current = next(int(line.split()[1]) * 1024 for line in status if line.startswith("VmSize"))
    resource.setrlimit(resource.RLIMIT_AS, (current + extra_bytes, current + extra_bytes))


def _child(connection, tool, case, budget_seconds):
    os.setpgrp()  # its own process group, so a timeout also kills what it started (qgis_process, GRASS)
    if not tool.external:
        limit_memory()
    try:
        geometry, seconds, runs = time_call(tool.run, case, budget_seconds=budget_seconds)
        measurement = measure(tool.name, case, geometry, seconds, runs)
        connection.send((measurement, geometry if case.extra.get("keep_geometry") else None))
    except Exception as error:  # noqa: BLE001 (a peer failing on an input is a result, not a crash)
        message = f"{type(error).__name__}: {error}".splitlines()[0][:160]
        connection.send((Measurement(tool.name, case.name, None, 0, error=message), traceback.format_exc()))
    finally:
        connection.close()


def run_tool(tool, case, timeout_seconds=90.0, budget_seconds=2.0):
    """Measure ``tool`` on ``case``; returns (Measurement, geometry or None).

    The geometry comes back only when ``case.extra["keep_geometry"]`` is true (for the plots).
    """
    context = multiprocessing.get_context("fork")
    receiver, sender = context.Pipe(duplex=False)
    process = context.Process(target=_child, args=(sender, tool, case, budget_seconds))
    process.start()
    sender.close()
    if receiver.poll(timeout_seconds):
        try:
            measurement, payload = receiver.recv()
        except EOFError:
            measurement, payload = Measurement(tool.name, case.name, None, 0, error="child died"), None
        process.join()
        geometry = payload if measurement.error == "" else None
        return measurement, geometry
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    process.join()
    return Measurement(tool.name, case.name, None, 0, error=f"timeout > {timeout_seconds:.0f} s"), None


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
            message = f"{type(error).__name__}: {error}".splitlines()[0][:160]
            connection.send((index, time.perf_counter() - started, None, message))
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
            connection.send((index, share, None, f"{type(outcome).__name__}: {outcome}".splitlines()[0][:160]))
        else:
            connection.send((index, share, None if outcome is None else shapely.to_wkb(outcome), ""))
    connection.send(None)
    connection.close()


def run_layer(tool, cases, timeout_seconds):
    """Run ``tool`` on every case in turn in one forked child, killed past ``timeout_seconds`` in all.

    Returns
    -------
    results : list of (seconds, geometry or None, error) or None
        One entry per case; None for the cases not reached before the time limit. ``seconds`` is the
        tool call alone (no transfer).
    note : str
        Empty, or why the run stopped early (time limit, child died).
    """
    context = multiprocessing.get_context("fork")
    receiver, sender = context.Pipe(duplex=False)
    process = context.Process(target=_layer_child, args=(sender, tool, cases))
    process.start()
    sender.close()
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
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    process.join()
    return results, note


def preload():
    """Import every tool library once in the parent so forked children start warm."""
    import centerline.geometry  # noqa: F401
    import label_centerlines  # noqa: F401
    import pygeoops  # noqa: F401
    import pysfcgal.geometry  # noqa: F401

    import incircu_plugin.core  # noqa: F401
