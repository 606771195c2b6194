"""The GIL is free while meshing, Ctrl-C stops a run, progress reaches Python."""
import os
import signal
import sys
import threading
import time

import pytest

import tubemesh


def test_a_second_python_thread_runs_while_meshing():
    # With a long switch interval Python never takes the GIL from the meshing thread: the
    # counter can move during mesh() only if mesh() released the GIL itself.
    ticks = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks[0] += 1
            time.sleep(0)  # yields the GIL, does not wait

    old = sys.getswitchinterval()
    sys.setswitchinterval(30)
    worker = threading.Thread(target=count)
    try:
        worker.start()
        while ticks[0] == 0:
            time.sleep(0)
        before = ticks[0]
        r = tubemesh.mesh("paper-ex2", size=1.1)
        during = ticks[0] - before
    finally:
        stop.set()
        worker.join()
        sys.setswitchinterval(old)
    assert len(r.tets) > 0
    assert during > 0


def test_ctrl_c_stops_a_run_and_the_next_one_works():
    seen = []

    def press_ctrl_c_in_the_tets(phase, done, total):
        seen.append(phase)
        if phase == "tets":
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        tubemesh.mesh("paper-ex3", size=40, progress=press_ctrl_c_in_the_tets)
    assert "tets" in seen and "check" not in seen
    r = tubemesh.mesh("paper-ex3", size=40)
    assert len(r.tets) > 0


def test_progress_reaches_python_and_its_errors_stop_the_run():
    phases = []
    tubemesh.mesh("paper-ex3", size=40, progress=lambda phase, done, total: phases.append((phase, done, total)))
    names = [p for p, _, _ in phases]
    for phase in ("build", "sweep", "surface", "pyramids", "tets", "check"):
        assert phase in names
    assert all(done <= total for _, done, total in phases if total)

    def fail(phase, done, total):
        if phase == "pyramids":
            raise ValueError("stop here")

    with pytest.raises(ValueError, match="stop here"):
        tubemesh.mesh("paper-ex3", size=40, progress=fail)
