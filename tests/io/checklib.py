"""Shared by the client tests: a scratch folder removed at exit, and a tally of named checks."""
import atexit, shutil, sys, tempfile


def scratch(prefix):
    """A temporary folder, removed when the test ends."""
    d = tempfile.mkdtemp(prefix=prefix)
    atexit.register(shutil.rmtree, d, True)
    return d


class Checks:
    """check(what, cond, why) records one check; finish() prints the failures and a summary
    line and exits 1 if any failed or fewer than `minimum` checks ran."""

    def __init__(self):
        self.bad, self.count = [], 0

    def __call__(self, what, cond, why=""):
        self.count += 1
        if not cond:
            self.bad.append(f"{what}: {why}")

    def finish(self, title, minimum):
        for b in self.bad:
            print("FAIL", b)
        print(f"{title}: {self.count - len(self.bad)}/{self.count} checks passed")
        sys.exit(1 if self.bad or self.count < minimum else 0)
