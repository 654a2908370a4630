"""The contact benchmark script runs in its smoke mode (no timings are asserted)."""

import subprocess
import sys
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[2] / "benchmarks" / "bench_contact.py"


def test_benchmark_quick_mode_prints_the_table():
    completed = subprocess.run(
        [sys.executable, str(SCRIPT), "--quick"], capture_output=True, text=True, timeout=120
    )
    assert completed.returncode == 0, completed.stderr
    rows = [
        line.split()
        for line in completed.stdout.splitlines()
        if line.startswith(("sphere", "ellipse"))
    ]
    assert [(row[0], row[1]) for row in rows] == [
        ("sphere", "64"), ("sphere", "128"), ("ellipse", "64"), ("ellipse", "128")
    ]  # fmt: skip
    for row in rows:
        assert abs(float(row[5])) < 2e-3, "peak pressure error against Hertz"
