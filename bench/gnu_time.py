"""Wall time and peak resident memory of commands, through GNU time (/usr/bin/time): what the
benchmark scripts that run the tubemesh program measure."""
import os
import subprocess
import sys
import tempfile
import time


def measured(commands, env=None, ok=(0,)):
    """Runs the commands side by side (stdout discarded, stderr shown); returns the wall seconds
    until the last ends and the largest peak RSS in KiB of any process in their trees (GNU time's
    %M covers waited-for descendants). Exits naming the command when its status is not in `ok`."""
    start = time.monotonic()
    procs = []
    for c in commands:
        fd, path = tempfile.mkstemp()
        os.close(fd)
        procs.append((subprocess.Popen(["/usr/bin/time", "-f", "%M", "-o", path] + c,
                                       stdout=subprocess.DEVNULL, env=env), path, c))
    peak = 0
    failed = None
    for p, path, c in procs:
        status = p.wait()
        if status not in ok and failed is None:
            failed = f"failed ({status}): {' '.join(c)}"
        with open(path) as f:
            text = f.read().split()
        os.remove(path)
        if text and text[-1].isdigit():
            peak = max(peak, int(text[-1]))
    if failed:
        sys.exit(failed)
    return time.monotonic() - start, peak
