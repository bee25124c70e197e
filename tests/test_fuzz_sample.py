"""A fixed-seed sample of the fuzz campaign (``fuzz/``): no untyped exception, hang, invalid result or crash.

About 2,000 small generated inputs (valid channels with islands and several parts, bank lines, compact shapes
with automatic ends, thin boxes, and hostile input), each in one of two worker processes with a 10 s limit.
The runner runs in its own interpreter (no QGIS in the workers). ``make fuzz N=100000`` runs the full campaign.
"""

import subprocess
import sys

import pytest

from tests.support.project import REPOSITORY

SAMPLE_SIZE = 2000
SAMPLE_SEED = 20261201


@pytest.mark.slow
def test_fixed_sample_has_no_untyped_error_hang_or_invalid_result():
    done = subprocess.run(
        [sys.executable, "-m", "fuzz", "--small", "--count", str(SAMPLE_SIZE), "--seed", str(SAMPLE_SEED)],
        cwd=REPOSITORY,
        capture_output=True,
        text=True,
        timeout=1200,
        check=False,
    )
    print(done.stdout)
    assert done.returncode == 0, done.stdout + done.stderr
    assert f"**{SAMPLE_SIZE}**" in done.stdout
