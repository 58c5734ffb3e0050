#!/usr/bin/env python3
"""The progress line of long runs (cli/progress.hpp), seen as a user sees it.

usage: progress_line.py FLIPFLOP WORKDIR

A run of several seconds (the sequential reference on 3*10^6 ball points)
under a pseudo-terminal must show `flipflop hull3: <stage> (<t> s)` on
standard error, rewritten in place, and erase it at the end (the last thing
written to the terminal is the erase sequence, so the shell prompt starts on a
clean line); the same run with standard error a pipe must write nothing there.
Its output file must equal the one written without a terminal.
"""
import os
import pty
import subprocess
import sys

flipflop, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
pts = os.path.join(work, "ball.xyz")
subprocess.run([flipflop, "gen", "ball", "3000000", "--seed", "5", "-o", pts], check=True)

# 1. standard error a pipe: nothing on it
out_pipe = os.path.join(work, "pipe.txt")
r = subprocess.run([flipflop, "hull3", pts, "--backend", "reference", "-o", out_pipe],
                   stdout=subprocess.PIPE, stderr=subprocess.PIPE)
assert r.returncode == 0, r.stderr
assert r.stderr == b"", r.stderr

# 2. standard error a terminal
out_tty = os.path.join(work, "tty.txt")
master, slave = pty.openpty()
p = subprocess.Popen([flipflop, "hull3", pts, "--backend", "reference", "-o", out_tty],
                     stdout=subprocess.DEVNULL, stderr=slave)
os.close(slave)
seen = b""
while True:
    try:
        chunk = os.read(master, 4096)
    except OSError:  # EIO: the child closed the terminal
        break
    if not chunk:
        break
    seen += chunk
assert p.wait() == 0
os.close(master)
text = seen.decode()
lines = [s for s in text.split("\r\x1b[K") if s]
assert lines, "no progress line on a terminal: %r" % text
assert all(s.startswith("flipflop hull3: ") and s.endswith(" s)") for s in lines), lines
stages = {s.split(": ", 1)[1].rsplit(" (", 1)[0].split(" ")[0] for s in lines}
assert stages <= {"reading", "computing", "certifying", "writing"}, stages
assert text.endswith("\r\x1b[K"), "the line is not erased at the end: %r" % text[-80:]
assert open(out_tty).read() == open(out_pipe).read()
print("progress line: %d updates, stages %s, erased at the end" % (len(lines), sorted(stages)))
