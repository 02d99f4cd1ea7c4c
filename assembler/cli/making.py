"""The commands that make files from specs: ``assembler new MODEL_FILE`` (a first spec for a vendor's
MJCF or URDF, every guess commented, or for a MuJoCo Menagerie model by name,
``menagerie:NAME[/ENTRY]``: :mod:`assembler.files.menagerie`), ``assembler scene`` (several placed
robots from a scene YAML, in one MJCF), ``assembler experiment`` (an experiment file's robots, with
their overrides, in one MJCF), ``assembler render`` (a PNG of the assembled robot in its home pose,
for reviewers) and ``assembler variants`` (one MJCF per variant of a robot: a grid, seeded random
draws, in parallel).

``experiment`` is a command of its own rather than a mode of ``scene``: an experiment with one robot
is that robot's standalone model (what ``build --set ...`` writes, no floor added), and the summary
line says which overrides each robot got, which is what a reviewer of an experiment wants to see.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Literal

from assembler.cli.common import assembled, gripper_choices, part_alone, robot_name
from assembler.errors import AssemblerError
from assembler.files import menagerie
from assembler.files.paths import display_path
from assembler.files.repositories import MARKER
from assembler.files.writing import write_atomically
from assembler.importers import NewSpec, write_new_spec
from assembler.importers.checking import build_problems
from assembler.importers.pack import importable, write_pack
from assembler.importers.packages import environment, found_packages
from assembler.mjcf.emit import to_xml
from assembler.models import RobotModel
from assembler.registry.catalog import applied_overrides
from assembler.registry.lookup import robot_class
from assembler.spec.part_arguments import DEFAULT, spec_file_path
from assembler.tools.render import encode_png, take_picture
from assembler.tools.render.picture import check_views
from assembler.worlds.experiment import load_experiment
from assembler.worlds.scene import load_scene
from assembler.worlds.variants import (
    MANIFEST,
    Draw,
    Grid,
    Progress,
    Shard,
    VariantPlan,
    failures,
    merge_shards,
    write_variants,
)


def run_new(args: argparse.Namespace) -> int:
    output = Path(args.output) if args.output else None
    model_file = Path(args.model_file)
    if args.model_file.startswith(menagerie.NEW_PREFIX):  # a Menagerie model by name
        model_file, served = menagerie.entry_file(args.model_file)
        print(f"{args.model_file}: {display_path(model_file)} ({served.license}, oid {served.oid[:12]})")
    if args.pack:
        return _pack(args, model_file)
    written, target = write_new_spec(model_file, output, args.kind, args.force, args.strict)
    # A package the user has still to declare is found for the check, as it will be once declared.
    pending = [package for package in written.packages if package.declared != "beside the spec"]
    jaws = written.jaw_paths(target)
    with found_packages(pending):
        problems = build_problems(target, written.kind, jaws)
    print(f"wrote {display_path(target)}{_and_jaws(jaws)}: {_what(written)}", end="")
    if len(pending) < len(written.packages):
        print(f" and {display_path(target.parent / MARKER)}", end="")
    if not _built_as_written(problems, " once the packages below are found" if pending else ""):
        return 1
    for package in pending:
        print(f"to do: {package.todo}")
    for name, value in environment(pending).items():
        print(f"  export {name}={value}")
    return 0


def _and_jaws(jaws: Sequence[Path]) -> str:
    return "".join(f" and {display_path(jaw)}" for jaw in jaws)


def _what(written: NewSpec) -> str:
    """``robot Pincher with its jaw PincherJaw`` (a bimanual robot's: ``with its jaws BaxterRightJaw and
    BaxterLeftJaw``): the kind and name of what ``new`` wrote."""
    names = [jaw.name for jaw in written.jaws]
    jaws = f" with its jaw{'s' if len(names) > 1 else ''} {' and '.join(names)}" if names else ""
    return f"{written.kind} {written.name}{jaws}"


def _built_as_written(problems: list[str], found: str = "") -> bool:
    """End the 'wrote ...' line with whether the written spec builds (its problems on stderr)."""
    if problems:
        print("; it does not build as written:")
        for line in problems:
            print(line, file=sys.stderr)
        return False
    print(f" (validated and compiled{found}); check each 'guess:' and settle each 'decide:' comment")
    return True


def _pack(args: argparse.Namespace, model_file: Path) -> int:
    """``new --pack DIR``: the spec written into a pack with the vendor's files
    (:mod:`assembler.importers.pack`)."""
    if args.output:
        raise AssemblerError(
            "new: give -o SPEC or --pack DIR, not both (a pack's spec goes in DIR/<package>/specs)"
        )
    pack = Path(args.pack)
    written = write_pack(model_file, pack, args.kind, args.force, args.strict)
    jaws = written.spec.jaw_paths(written.spec_path)
    with importable(pack.resolve()):  # the pack's package:// names resolve as once it is installed
        problems = build_problems(written.spec_path, written.spec.kind, jaws)
    print(
        f"wrote {display_path(written.spec_path)}{_and_jaws(jaws)}: {_what(written.spec)}, and "
        f"{written.copied} vendor files under {display_path(pack / written.package / 'assets')}",
        end="",
    )
    if written.pyproject_written:
        print(f" and {display_path(pack / 'pyproject.toml')}", end="")
    if not _built_as_written(problems):
        return 1
    if not written.licences:
        print(
            "decide: no licence file lies beside the vendor's files: add the licence you may share them "
            f"under to {display_path(pack / written.package / 'assets')}"
        )
    if not written.pyproject_written:
        print(
            f"to do: {display_path(pack / 'pyproject.toml')} exists and was kept; declare "
            f'[project.entry-points."robot_assembler.specs"] {written.package} = "{written.package}:specs"'
        )
    print(f"publish it: python -m build {display_path(pack)}, then pip install the wheel")
    return 0


def _write_mjcf(xml: str, output: str | None, contents: str) -> None:
    """``xml`` written to ``output`` (then ``wrote OUTPUT`` and ``contents`` on stderr), or to stdout."""
    if output:
        write_atomically(Path(output), xml)
        print(f"wrote {display_path(output)}{contents}", file=sys.stderr)
    else:
        sys.stdout.write(xml)


def run_scene(args: argparse.Namespace) -> int:
    scene = load_scene(args.scene)
    scene.get_model()  # compile first: a scene that does not compile writes nothing
    names = ", ".join(robot.name for robot in scene.robots)
    _write_mjcf(to_xml(scene.mjspec), args.output, f" ({names})")
    return 0


def robot_and_overrides(robot: RobotModel) -> str:
    """``Sparrow70 (joint_defaults.damping=0.2)``: a robot and the overrides it was built with."""
    changes = applied_overrides(type(robot))
    if not changes:
        return robot.name
    return f"{robot.name} ({', '.join(f'{c.key}={json.dumps(c.value, default=str)}' for c in changes)})"


def run_experiment(args: argparse.Namespace) -> int:
    experiment = load_experiment(args.experiment)
    xml = experiment.get_xml()  # compiled first: an experiment that does not compile writes nothing
    names = ", ".join(robot_and_overrides(robot) for robot in experiment.robots)
    _write_mjcf(xml, args.output, f": {names}")
    return 0


def run_render(args: argparse.Namespace) -> int:
    views = [view.strip() for view in args.views.split(",") if view.strip()]
    check_views(views)  # before the robot is built: a typo should fail fast
    width, height = args.size
    part = part_alone(args) or assembled(args)  # a gripper or base spec alone, as build makes it
    picture = take_picture(part, views, width, height, args.labels, args.groups)
    target = Path(args.output)
    write_atomically(target, encode_png(picture.image))
    height, width, _ = picture.image.shape
    print(
        f"wrote {display_path(target)} ({width}x{height}, {', '.join(views)}; {picture.shown})",
        file=sys.stderr,
    )
    return 0


def plan_from(args: argparse.Namespace) -> VariantPlan:
    """The variant plan the flags describe; flag mistakes are errors naming the flag (the plan's rules)."""
    name = robot_name(args.robot)
    laws: tuple[Literal["uniform", "normal"], ...] = ("uniform", "normal")
    draws = tuple(Draw.parse(text, law) for law in laws for text in getattr(args, law))
    grids = tuple(Grid.parse(text) for text in args.grid)
    grippers = gripper_choices(args.gripper)
    if args.no_grippers:
        grippers = {arm: None for arm in getattr(robot_class(name).spec, "arms", ())}
    spec_file = spec_file_path(args.robot)
    robot_file = [str(spec_file)] if spec_file is not None else []
    return VariantPlan(
        robot=name,
        idn=args.idn,
        base=None if args.no_base else (args.base or DEFAULT),
        grippers=tuple(grippers.items()),
        fixed=tuple(args.overrides),
        grids=grids,
        draws=draws,
        random=args.random,
        seed=args.seed,
        spec_paths=(*(str(Path(p).resolve()) for p in args.specs), *robot_file),
        cache=not args.no_cache,
        store=args.cache,
        jobs=args.jobs,
    )


LARGE = 10_000
"""From this many variants a run states its size first and reports progress as it goes."""

PROGRESS_SECONDS = 5.0
"""How often a long run says how far it is."""


def _progress(robot: str) -> Progress:
    """Say every few seconds how many of the run's variants are done (a long run is never silent)."""
    said = time.monotonic()

    def tell(done: int, count: int) -> None:
        nonlocal said
        now = time.monotonic()
        if now - said >= PROGRESS_SECONDS and done < count:
            said = now
            print(f"variants of {robot}: {done:,} of {count:,} done ({done / count:.1%})", file=sys.stderr)

    return tell


def run_variants(args: argparse.Namespace) -> int:
    plan = plan_from(args)
    folder = display_path(args.output)
    if args.merge is not None:
        listed = merge_shards(plan, args.output, args.merge)
        manifest = display_path(Path(args.output) / MANIFEST)
        print(
            f"merged {args.merge} shards of {plan.robot} in {folder}: {manifest} lists {listed}",
            file=sys.stderr,
        )
        return 0
    shard = Shard.parse(args.shard) if args.shard is not None else None
    count = plan.size if shard is None else len(plan.shard(shard.number, shard.shards))
    if plan.size >= LARGE:
        part = "" if shard is None else f"; shard {shard.number}/{shard.shards}: {count:,} of them"
        print(f"a plan of {plan.size:,} variants of {plan.robot}{part}", file=sys.stderr)
    run = write_variants(plan, args.output, shard, _progress(plan.robot))
    manifest = display_path(Path(args.output) / (MANIFEST if shard is None else shard.manifest_name))
    models = f"{run.distinct} distinct model{'s' if run.distinct != 1 else ''}"
    written = f"wrote {len(run.written)} of {len(run.results)} variants of {plan.robot}"
    print(f"{written} to {folder} ({manifest}): {models}", file=sys.stderr)  # as every command's "wrote"
    for key in run.no_effect:
        print(
            f"warning: {plan.flag_of(key)} {key} changes nothing in the compiled model (variants that differ "
            "only in it are byte-identical); see what else in the spec sets it",
            file=sys.stderr,
        )
    problems = failures(run.results)
    for problem in problems:
        print(str(problem), file=sys.stderr)
    return 1 if problems else 0
