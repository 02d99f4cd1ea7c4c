"""``robot-assembler.lock``: the files each robot's build reads, by sha256, so a review sees that a mesh
or a vendor's URDF changed under an unchanged spec.

``assembler lock [PATHS]`` builds each robot of the specs it covers (without PATHS: the repository's
spec folders) with its default base and grippers, without compiling, and writes at the repository's
root, one line per file, grouped by robot:

- ``spec``: its spec file, the specs it ``extends``, the motor specs it names, and the same for its
  base and grippers;
- ``model``: the MJCF or URDF its spec names and every file that includes;
- ``asset``: the meshes, textures and height fields the assembly names (files MuJoCo reads, not the
  cache's converted copies, which are derived from a ``model`` or ``asset`` file);
- ``package``: the installed distribution a ``package://`` name resolved to, with its version, and
  the MuJoCo Menagerie model a ``menagerie://`` name resolved to, with its git tree id;

and MuJoCo's version at the top. Paths are relative to the root inside the repository,
``package://NAME/...`` inside an installed package, ``shipped:...`` for robot-assembler's own
specs and assets, absolute elsewhere. The text is sorted and
stable, so a lock change reads as a diff of lines.

``assembler validate --locked`` hashes the files the lock lists, nothing else (no spec is read, no
robot built): a file whose bytes changed, a file gone, a package of another version or another
MuJoCo is one line each, naming the robots it affects. A change to what a robot reads (a new include,
a new mesh) is a change to a file already listed (the spec, the MJCF that includes it), so it is
caught too. Locking is opt-in: nothing else reads the lock, and no build is slower for it.
"""

from __future__ import annotations

import hashlib
import importlib.metadata
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import mujoco

from assembler.answers.request import part_origins
from assembler.cache.dependencies import asset_files
from assembler.errors import AssemblerError, Problem
from assembler.files import menagerie
from assembler.files.cache_location import volatile_folders
from assembler.files.menagerie import MENAGERIE_SCHEME
from assembler.files.paths import (
    PACKAGE_SCHEME,
    display_path,
    package_root,
    shipped_assets_dir,
    shipped_specs_dir,
)
from assembler.files.repositories import find_repository
from assembler.files.writing import write_atomically
from assembler.models import RobotModel
from assembler.registry.catalog import register_specs
from assembler.registry.instances import assemble
from assembler.urdf.packages import package_folders

LOCK_FILE = "robot-assembler.lock"

SHIPPED = "shipped:"
"""How the lock names a file robot-assembler ships (``shipped:specs/bases/pedestal.yaml``), wherever
the installed copy lies."""

HEADER = (
    "# robot-assembler.lock: every file each robot's build reads, by sha256 (written by `assembler lock`).\n"
    "# `assembler validate --locked` fails when one changes; run `assembler lock` again to accept it.\n"
)


@dataclass
class RobotLock:
    """What one robot's build reads: (kind, path as written in the lock) -> sha256, and packages."""

    name: str
    files: dict[tuple[str, str], str] = field(default_factory=dict)
    packages: dict[str, str] = field(default_factory=dict)
    """``package://`` name -> the version of the distribution that provides it."""


@dataclass
class Lock:
    """A lock file's content."""

    mujoco: str
    robots: dict[str, RobotLock]

    def text(self) -> str:
        """The lock as written: sorted, one line per file or package, a blank line between robots."""
        blocks = [f"mujoco {self.mujoco}"]
        for name in sorted(self.robots):
            robot = self.robots[name]
            lines = [f"robot {name}"]
            lines += [f"  package {package} {version}" for package, version in sorted(robot.packages.items())]
            lines += [f"  {kind} {path} {digest}" for (kind, path), digest in sorted(robot.files.items())]
            blocks.append("\n".join(lines))
        return HEADER + "\n" + "\n\n".join(blocks) + "\n"


def _digest(path: Path) -> str | None:
    try:
        return hashlib.sha256(path.read_bytes()).hexdigest()
    except OSError:
        return None


def _version(package: str) -> str:
    """The version of the installed distribution providing the import package ``package``."""
    names = [package, *importlib.metadata.packages_distributions().get(package, [])]
    for name in names:
        try:
            return importlib.metadata.version(name)
        except importlib.metadata.PackageNotFoundError:
            continue
    return "unknown"


def _package_folder(name: str) -> Path | None:
    """Where ``package://NAME`` leads: an importable package, else a ROS package folder (a URDF's)."""
    found = package_root(name)
    folders = [found] if found is not None else package_folders(name)
    return folders[0].resolve() if folders else None


class _Namer:
    """How a file is written in the lock (and found again from it)."""

    def __init__(self, root: Path) -> None:
        self.root = root
        self.packages: dict[str, Path] = {}
        self.menagerie: dict[str, Path] = {}
        """Menagerie model name -> its folder, for the models the specs name."""
        self.shipped = {
            folder.name: folder.resolve() for folder in (shipped_specs_dir(), shipped_assets_dir())
        }

    def package_of(self, reference: str) -> None:
        """Note the package a spec's ``package://NAME/...`` (or Menagerie model a ``menagerie://``)
        reference names."""
        if reference.startswith(MENAGERIE_SCHEME):
            _, model_folder = menagerie.locate(reference)
            self.menagerie[reference.split("/", 3)[2].split("@")[0]] = model_folder.resolve()
        elif reference.startswith(PACKAGE_SCHEME):
            name = reference[len(PACKAGE_SCHEME) :].split("/", 1)[0]
            folder = _package_folder(name)
            if folder is not None:
                self.packages[name] = folder

    def name(self, file: str | Path) -> str:
        """Inside a package the spec names, then robot-assembler's own folders, then the repository."""
        path = Path(file).resolve()
        for package, folder in self.packages.items():
            if path.is_relative_to(folder):
                return f"{PACKAGE_SCHEME}{package}/{path.relative_to(folder).as_posix()}"
        for model, folder in self.menagerie.items():
            if path.is_relative_to(folder):
                oid = (menagerie.oid_now(model) or "")[: menagerie.OID_DIGITS]
                return f"{MENAGERIE_SCHEME}{model}@{oid}/{path.relative_to(folder).as_posix()}"
        for kind, folder in self.shipped.items():
            if path.is_relative_to(folder):
                return f"{SHIPPED}{kind}/{path.relative_to(folder).as_posix()}"
        if path.is_relative_to(self.root):
            return path.relative_to(self.root).as_posix()
        return path.as_posix()

    def path(self, name: str) -> Path:
        """The file a lock line names, where it is now."""
        if name.startswith(PACKAGE_SCHEME):
            package, _, inside = name[len(PACKAGE_SCHEME) :].partition("/")
            folder = _package_folder(package)
            return (folder / inside) if folder is not None else Path(name)
        if name.startswith(MENAGERIE_SCHEME):
            try:
                return menagerie.locate(name)[0]
            except AssemblerError:
                return Path(name)  # gone: its digest is None
        if name.startswith(SHIPPED):
            kind, _, inside = name[len(SHIPPED) :].partition("/")
            return self.shipped.get(kind, Path(name)) / inside
        path = Path(name)
        return path if path.is_absolute() else self.root / path


def _inside(file: str, folders: Sequence[Path]) -> bool:
    path = Path(file).resolve()
    return any(path.is_relative_to(folder) for folder in folders)


def _robot_lock(robot: RobotModel, namer: _Namer) -> RobotLock:
    locked = RobotLock(type(robot).__name__)
    parts = [robot, *robot.models]
    for part in parts:
        for reference in (getattr(part.spec, "mjcf", None), getattr(part.spec, "urdf", None)):
            if isinstance(reference, str):
                namer.package_of(reference)
    files: list[tuple[str, str]] = [
        ("spec", origin.path) for part in parts for origin in part_origins(type(part))
    ]
    files += [("model", path) for part in parts for path, _, _ in part.source.files]
    derived = [folder.resolve() for folder in volatile_folders()]
    files += [("asset", path) for path in asset_files(robot.mjspec)]
    derived_files = {str(Path(file).resolve()) for _, file in files if _inside(file, derived)}
    seen: set[str] = set()
    for kind, file in files:  # a file once, under the first kind that reads it
        name = namer.name(file)
        digest = _digest(Path(file))
        if digest is not None and name not in seen and str(Path(file).resolve()) not in derived_files:
            seen.add(name)
            locked.files[(kind, name)] = digest
    used = {name.split("/", 3)[2] for _, name in locked.files if name.startswith(PACKAGE_SCHEME)}
    locked.packages = {package: _version(package) for package in sorted(used)}
    models = {
        name.split("/", 3)[2].split("@")[0] for _, name in locked.files if name.startswith(MENAGERIE_SCHEME)
    }
    locked.packages |= {f"{menagerie.NEW_PREFIX}{model}": menagerie.oid_now(model) or "?" for model in models}
    return locked


def lock_root(paths: Sequence[str | Path]) -> Path:
    """Where the lock lives: the root of the spec repository holding the first path (or the working
    folder), else that folder itself."""
    start = Path(paths[0]) if paths else Path.cwd()
    folder = start if start.is_dir() else start.parent
    repository = find_repository(folder)
    return repository.root if repository is not None else folder.resolve()


def covered_paths(paths: Sequence[str | Path]) -> list[Path]:
    """``paths``, or the spec folders of the repository holding the working folder."""
    if paths:
        return [Path(path) for path in paths]
    repository = find_repository(Path.cwd())
    if repository is None:
        raise AssemblerError(
            "lock: not inside a spec repository (README: Spec repositories); give spec files or folders"
        )
    return list(repository.specs)


def make_lock(paths: Sequence[str | Path], root: Path) -> Lock:
    """The lock of every robot among the specs at ``paths``."""
    robots = [cls for cls in register_specs(*paths) if issubclass(cls, RobotModel)]
    if not robots:
        shown = ", ".join(display_path(path) for path in paths)
        raise AssemblerError(f"lock: no robot spec in {shown}; a lock covers robots (with their parts)")
    namer = _Namer(root)
    locks = [_robot_lock(assemble(cls.__name__), namer) for cls in robots]
    return Lock(mujoco.__version__, {lock.name: lock for lock in locks})


def write_lock(paths: Sequence[str | Path]) -> tuple[Path, Lock]:
    """Write the lock of ``paths`` (default: the repository's specs) at the repository's root."""
    covered = covered_paths(paths)
    root = lock_root(covered)
    lock = make_lock(covered, root)
    target = root / LOCK_FILE
    write_atomically(target, lock.text())
    return target, lock


def read_lock(path: Path) -> Lock:
    """A lock file's content; one line naming the line when it is not a lock."""
    try:
        text = path.read_text()
    except OSError as error:
        raise AssemblerError(
            f"{display_path(path)}: cannot read it ({error.strerror}); run `assembler lock`"
        ) from None
    return parse_lock(text, display_path(path))


def parse_lock(text: str, shown: str) -> Lock:
    """A lock's text as a :class:`Lock`; ``shown`` names it in the one line a malformed line gets."""
    lock = Lock("", {})
    current: RobotLock | None = None
    for number, line in enumerate(text.splitlines(), 1):
        words = line.split()
        if not words or words[0].startswith("#"):
            continue
        if words[0] == "mujoco" and len(words) == 2:
            lock.mujoco = words[1]
        elif words[0] == "robot" and len(words) == 2:
            current = lock.robots.setdefault(words[1], RobotLock(words[1]))
        elif current is not None and words[0] == "package" and len(words) == 3:
            current.packages[words[1]] = words[2]
        elif current is not None and words[0] in ("spec", "model", "asset") and len(words) == 3:
            current.files[(words[0], words[1])] = words[2]
        else:
            raise AssemblerError(
                f"{shown}:{number}:1: not a line of a lock file; write it again with `assembler lock`"
            )
    return lock


def _affecting(robots: Iterable[str]) -> str:
    return f"affects {', '.join(sorted(set(robots)))}"


def drift(lock_path: Path) -> list[Problem]:
    """One problem per locked file whose bytes changed or that is gone, per package of another
    version, and for another MuJoCo; each names the robots it affects."""
    lock = read_lock(lock_path)
    namer = _Namer(lock_path.parent.resolve())
    shown = display_path(lock_path)
    problems: list[Problem] = []
    if lock.mujoco != mujoco.__version__:
        problems.append(
            Problem(
                f"{shown}: locked with MuJoCo {lock.mujoco}, this is {mujoco.__version__}; "
                "affects every robot"
            )
        )
    files: dict[str, tuple[str, list[str]]] = {}
    packages: dict[str, tuple[str, list[str]]] = {}
    for robot in lock.robots.values():
        for (_, name), digest in robot.files.items():
            files.setdefault(name, (digest, []))[1].append(robot.name)
        for package, version in robot.packages.items():
            packages.setdefault(package, (version, []))[1].append(robot.name)
    for package, (version, robots) in sorted(packages.items()):
        if package.startswith(menagerie.NEW_PREFIX):  # a Menagerie model: its git tree id
            now = menagerie.oid_now(package[len(menagerie.NEW_PREFIX) :]) or "not served"
        else:
            now = _version(package) if _package_folder(package) is not None else "not installed"
        if now != version:
            problems.append(
                Problem(f"package {package}: {version} in the lock, {now} now; {_affecting(robots)}")
            )
    for name, (digest, robots) in sorted(files.items()):
        found = _digest(namer.path(name))
        if found != digest:
            state = "gone" if found is None else f"sha256 {found[:12]} now"
            problems.append(
                Problem(f"{name}: sha256 {digest[:12]} in the lock, {state}; {_affecting(robots)}")
            )
    return problems


def check_locked(start: Path | None = None) -> tuple[Path, int]:
    """Check the repository's lock (found from ``start``, default the working folder): the lock's
    path and how many files it holds, or :class:`AssemblerError` with one line per drift."""
    root = lock_root([start] if start is not None else [])
    path = root / LOCK_FILE
    if not path.is_file():
        raise AssemblerError(f"{display_path(path)}: no lock here; write one with `assembler lock`")
    problems = drift(path)
    if problems:
        problems.append(Problem(f"{display_path(path)}: run `assembler lock` to accept these changes"))
        raise AssemblerError(problems)
    return path, sum(len(robot.files) for robot in read_lock(path).robots.values())


def lock_changes(before: Lock, after: Lock) -> list[str]:
    """A lock change as the robots it changes: for each robot whose files or packages differ, one line
    naming it and one per file or package (old and new digest or version); MuJoCo's version first."""
    lines = (
        [f"mujoco {before.mujoco} -> {after.mujoco}: every robot"] if before.mujoco != after.mujoco else []
    )
    for name in sorted({*before.robots, *after.robots}):
        old, new = before.robots.get(name), after.robots.get(name)
        if old is None or new is None:
            lines.append(f"robot {name}: {'added' if old is None else 'removed'}")
            continue
        changed = [
            f"  package {package}: {old.packages.get(package, '-')} -> {new.packages.get(package, '-')}"
            for package in sorted({*old.packages, *new.packages})
            if old.packages.get(package) != new.packages.get(package)
        ]
        changed += [
            f"  {kind} {path}: {_short(old.files.get((kind, path)))} -> {_short(new.files.get((kind, path)))}"
            for kind, path in sorted({*old.files, *new.files})
            if old.files.get((kind, path)) != new.files.get((kind, path))
        ]
        if changed:
            lines += [f"robot {name}: {len(changed)} change{'s' if len(changed) != 1 else ''}", *changed]
    return lines


def _short(digest: str | None) -> str:
    return "-" if digest is None else digest[:12]
