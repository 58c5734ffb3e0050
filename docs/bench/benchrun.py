"""Shared by measure_hull3.py, measure_rt2.py and measure_rt3.py: one `flipflop bench ... --csv`
line (all rows from one process, the bench's `identical` verdict kept: a line
whose outputs differ stops the script) and the CSV tables with their notes."""
import csv
import io
import os
import subprocess
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))


class Runner:
    def __init__(self, flipflop, script, reps):
        self.flipflop, self.script, self.reps = flipflop, script, reps
        self.stamp = time.strftime("%Y-%m-%d")

    def bench(self, kind, args, run, reps=None, identical=True):
        """identical=False: peers may break ties their own way (degenerate input)"""
        out = subprocess.run([self.flipflop, "bench", kind] + args + ["--reps", reps or self.reps, "--csv", "--run", run],
                             check=True, capture_output=True, text=True).stdout
        rows = list(csv.DictReader(io.StringIO(self._data(out))))
        if identical and not all(r["identical"] == "1" for r in rows):
            sys.exit("outputs differ: %s %s %s" % (kind, args, out))
        return rows

    def stages(self, kind, args):
        out = subprocess.run([self.flipflop, "bench", kind, "--stages"] + args + ["--reps", self.reps, "--csv"],
                             check=True, capture_output=True, text=True).stdout
        return list(csv.DictReader(io.StringIO(self._data(out))))

    def _data(self, out):
        """The CSV without the comment lines `flipflop bench --csv` starts with
        (the command, `# machine: ...`); the last machine line is kept for write()."""
        lines = out.splitlines(keepends=True)
        for line in lines:
            if line.startswith("# machine: "):
                self.machine = line[len("# machine: "):].strip()
        return "".join(line for line in lines if not line.startswith("#"))

    def write(self, name, header, lines, note):
        with open(os.path.join(here, name), "w") as f:
            f.write("# %s\n# measured %s on the 2-core development VM by %s; load average %.2f at the end\n"
                    % (note, self.stamp, self.script, os.getloadavg()[0]))
            if getattr(self, "machine", None):
                f.write("# machine (the last bench run's): %s\n" % self.machine)
            w = csv.writer(f, lineterminator="\n")
            w.writerow(header)
            w.writerows(lines)
