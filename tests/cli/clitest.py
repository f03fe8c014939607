"""What the CLI test scripts share: one line per check ("ok   what" / "FAIL what"), the
failed ones kept in `failures`, and running the program under test with a timeout."""
import subprocess

failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


def run(cli, *args, timeout=120):
    return subprocess.run([cli, *args], capture_output=True, text=True, timeout=timeout)
