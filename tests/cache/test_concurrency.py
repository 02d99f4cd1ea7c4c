"""Many builders at once, and builders killed half way, with one shared compiled-model cache.

Eight ``assembler build`` processes run together twice (a cold cache that they all fill, then a
warm one they all read): every build succeeds with the output a lone, uncached build writes, and
every cache entry loads afterwards. A build killed at any moment leaves the user's old output or
a whole new one, and the next build succeeds from whatever the killed one left in the cache.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import mujoco
import pytest

from assembler.cache import ModelStore
from assembler.cache.entry import MANIFEST_SUFFIX, MODEL_SUFFIX, XML_SUFFIX
from assembler.cli import main
from assembler.files.paths import package_root

CLI = "import sys; from assembler.cli import run; sys.exit(run())"

BUILDS: list[list[str]] = [
    ["Sparrow7"],
    ["Sparrow7"],
    ["Sparrow7"],
    ["Sparrow7"],
    ["Finch6"],
    ["TwinTorso"],
    ["Biped"],
    ["Sparrow7", "--base", "QuadrupedBase"],
]
"""Four builders of one robot and four of others, all at once."""

OLD = "<mujoco model='the user's previous output'/>\n"


def _environment(cache: Path) -> dict[str, str]:
    return {**os.environ, "ASSEMBLER_CACHE_DIR": str(cache), "PYTHONDONTWRITEBYTECODE": "1"}


def _finish(process: subprocess.Popen[str]) -> tuple[int, str]:
    """Exit code and standard error of a process, once it has ended (its pipe closed)."""
    _, err = process.communicate(timeout=900)
    return process.returncode, err


def _start(arguments: list[str], out: Path, cache: Path) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-c", CLI, "build", *arguments, "-o", str(out)],
        cwd=out.parent,  # MuJoCo's log file, if any, lands beside the outputs
        env=_environment(cache),
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
    )


def _references(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> dict[str, bytes]:
    """What each distinct build writes alone, without the cache."""
    monkeypatch.setenv("ASSEMBLER_NO_CACHE", "1")
    folder = tmp_path / "reference"
    references = {}
    for arguments in BUILDS:
        key = " ".join(arguments)
        if key not in references:
            out = folder / f"{len(references)}.xml"
            assert main(["build", *arguments, "-o", str(out)]) == 0
            references[key] = out.read_bytes()
    monkeypatch.delenv("ASSEMBLER_NO_CACHE")
    return references


def _check_cache(cache: Path) -> int:
    """Every entry loads (its XML too, when it has one); only whole entries and their model and
    XML files are there. Returns the count."""
    store = ModelStore(cache, 2 * 1024**3)
    names = sorted(os.listdir(cache))
    manifests = [n for n in names if n.endswith(MANIFEST_SUFFIX) and not n.startswith(".")]
    for manifest in manifests:
        key = manifest.removesuffix(MANIFEST_SUFFIX)
        assert store.load(key) is not None, manifest
        entry = store.entry(key)
        if entry is not None and entry.xml:
            assert store.load_xml(key) is not None, manifest
    strays = [
        n
        for n in names
        if not n.startswith(".")
        # a writer killed before its manifest leaves its model and XML files: no manifest names them,
        # so nothing reads them, and eviction removes them once they are GRACE_SECONDS old
        and not n.endswith((MANIFEST_SUFFIX, MODEL_SUFFIX, XML_SUFFIX))
        and n not in ("meshes", "requests")
    ]  # the mesh store's and the request records' folders; their own tests check their files
    assert strays == []
    return len(manifests)


def test_eight_processes_building_at_once_all_succeed_with_identical_outputs(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    references = _references(tmp_path, monkeypatch)
    cache = tmp_path / "cache"
    for round_ in ("cold", "warm"):
        folder = tmp_path / round_
        folder.mkdir()
        outs = [folder / f"build{i}.xml" for i in range(len(BUILDS))]
        processes = [_start(arguments, out, cache) for arguments, out in zip(BUILDS, outs, strict=True)]
        results = [_finish(p) for p in processes]
        assert results == [(0, f"wrote {out.name}\n") for out in outs]
        for arguments, out in zip(BUILDS, outs, strict=True):
            assert out.read_bytes() == references[" ".join(arguments)], (round_, arguments)
        assert sorted(os.listdir(folder)) == sorted(out.name for out in outs)  # no temporary files
        assert not any(name.endswith(".tmp") for name in os.listdir(cache))
        assert _check_cache(cache) == len(references)


def _kill_when(process: subprocess.Popen[str], cache: Path, delay: float) -> str:
    """SIGKILL ``process`` after ``delay`` seconds, or as soon as it starts writing to the cache
    when ``delay`` is negative. Returns what it was doing."""
    start = time.monotonic()
    while process.poll() is None:
        writing = delay < 0 and cache.is_dir() and any(n.endswith(".tmp") for n in os.listdir(cache))
        if writing or 0 <= delay <= time.monotonic() - start:
            process.send_signal(signal.SIGKILL)
            _finish(process)
            return "killed while writing the cache" if writing else f"killed after {delay:.2f} s"
        time.sleep(0.0005)
    _finish(process)
    return "finished before the kill"


def test_a_build_killed_at_any_moment_leaves_old_or_whole_files_and_a_usable_cache(tmp_path: Path) -> None:
    # robosuite's Panda writes a 44 MB cache entry: a wide window to be killed in.
    robot = "Panda" if package_root("robosuite") else "Biped"
    out = tmp_path / "out" / "robot.xml"
    out.parent.mkdir()
    timing = tmp_path / "timing"
    timing.mkdir()
    start = time.monotonic()
    assert _finish(_start([robot], timing / "robot.xml", tmp_path / "timing-cache"))[0] == 0
    duration = time.monotonic() - start
    outcomes = []
    for attempt, delay in enumerate([-1.0, 0.3 * duration, 0.6 * duration, 0.8 * duration, 0.95 * duration]):
        cache = tmp_path / f"cache{attempt}"
        out.write_text(OLD)
        outcomes.append(_kill_when(_start([robot], out, cache), cache, delay))
        assert out.read_text() == OLD or mujoco.MjModel.from_xml_path(str(out)).nbody > 1
        assert _finish(_start([robot], out, cache)) == (0, "wrote robot.xml\n")
        assert out.read_bytes() == (timing / "robot.xml").read_bytes()
        assert _check_cache(cache) == 1
    print(f"{robot}: " + "; ".join(outcomes))  # shown with pytest -s
