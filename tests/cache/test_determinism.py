"""The same inputs give byte-identical MJCF in separate processes, whatever Python's hash seed: no
set or dict ordering, memory address or clock leaks into what a user commits or diffs."""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

ROBOTS = ["Sparrow7", "TwinTorso"]
if importlib.util.find_spec("robosuite") is not None:
    ROBOTS += ["Panda", "Tiago", "SpotWithArmFloating", "GR1"]  # mount, mobile, legged, humanoid

BUILD = """
import sys
from pathlib import Path
import numpy as np
import assembler

out = Path(sys.argv[1])
for name in sys.argv[2:]:
    robot = assembler.assemble(name, idn="d1")
    robot.set_base_xpos(np.array([0.3, -0.2, 0.1]))
    robot.set_base_ori(np.array([0.3, -0.5, 1.2]))
    (out / f"{name}.xml").write_bytes(robot.get_xml().encode())
"""


def _start(folder: Path, seed: str, cache: Path) -> subprocess.Popen[str]:
    folder.mkdir()
    # Each process compiles and emits (no cache answers for it), into a cache folder of its own.
    env = dict(os.environ, PYTHONHASHSEED=seed, ASSEMBLER_CACHE_DIR=str(cache), ASSEMBLER_NO_CACHE="1")
    command = [sys.executable, "-c", BUILD, str(folder), *ROBOTS]
    return subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


SEEDS = ("0", "1", "4242")


def test_the_same_robots_give_byte_identical_xml_across_processes_and_hash_seeds(tmp_path: Path) -> None:
    processes = [_start(tmp_path / f"seed{seed}", seed, tmp_path / f"cache{seed}") for seed in SEEDS]
    for process in processes:  # all at once: the processes overlap in time, too
        _, errors = process.communicate(timeout=600)
        assert process.returncode == 0, errors
    first = tmp_path / f"seed{SEEDS[0]}"
    for seed in SEEDS[1:]:
        for name in ROBOTS:
            ours, theirs = (
                (first / f"{name}.xml").read_bytes(),
                (tmp_path / f"seed{seed}" / f"{name}.xml").read_bytes(),
            )
            assert ours == theirs, f"{name}: the XML differs between PYTHONHASHSEED {SEEDS[0]} and {seed}"
