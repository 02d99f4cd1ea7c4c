"""Every command's arguments, and nothing heavier than ``argparse``: ``assembler --help`` and a typo in
a flag answer without importing MuJoCo, numpy or pydantic. Each command's ``run_<command>(args)`` lives
in the module of its kind of command, imported only when that command runs (:data:`COMMANDS`).
"""

from __future__ import annotations

import argparse
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from assembler.mjcf import GROUP_COUNT

Define = Callable[[argparse.ArgumentParser], None]

REPORT_FORMATS: dict[str, str] = {
    "text": "lines for people (default)",
    "json": "for tools",
    "github": "GitHub Actions annotations",
}
"""Output formats of problems and findings (validate, lint) and what each is for."""

DIFF_FORMATS: tuple[str, ...] = ("json", "markdown", "text")
"""``assembler diff``'s formats (``assembler.tools.diff.FORMATS``; a test keeps them equal)."""

VIEWS: tuple[str, ...] = ("front", "side", "top", "iso")
"""``assembler render``'s views (``assembler.tools.render.VIEWS``; a test keeps them equal)."""

LINT_TARGETS: tuple[str, ...] = ("mujoco", "mjwarp", "mjx")
"""``assembler lint --target`` choices (``assembler.tools.lint.ENGINES``; a test keeps them equal)."""

BUILD_TARGETS: tuple[str, ...] = ("mujoco", "mjwarp")
"""``assembler build --target`` choices: MuJoCo alone, or also MuJoCo Warp's put_model."""

LABELS: tuple[str, ...] = ("bodies", "joints", "sites")
"""``assembler render --labels`` choices (``assembler.tools.render.LABELS``; a test keeps them equal)."""

MAX_SIDE = 8192
"""Largest view width or height accepted (MuJoCo allocates an offscreen buffer of that size)."""


def add_global_options(parser: argparse.ArgumentParser, after_command: bool) -> None:
    """``--specs`` and ``--allow-path``, before the command or after it (kept apart, then joined)."""
    suffix = "_after" if after_command else ""
    parser.add_argument(
        "--specs",
        action="append",
        default=[],
        dest="specs" + suffix,
        metavar="DIR",
        help="also register the specs in DIR (repeatable)",
    )
    parser.add_argument(
        "--allow-path",
        action="append",
        default=[],
        dest="allow_path" + suffix,
        metavar="DIR",
        help="let specs read files below DIR too (repeatable); by default a spec reads only its own "
        "folder, the shipped specs and assets, and package:// paths (see SECURITY.md)",
    )


def add_override_argument(parser: argparse.ArgumentParser) -> None:
    """``--set PATH=VALUE``: change a spec field for this run (the registered robot stays as it is)."""
    parser.add_argument(
        "--set",
        action="append",
        default=[],
        dest="overrides",
        metavar="PATH=VALUE",
        help="override a spec field, typed by the schema (repeatable), "
        "e.g. joint_defaults.damping=0.2 or init_qpos[3]=-2.0",
    )


def add_assembly_arguments(parser: argparse.ArgumentParser, cached: bool = True) -> None:
    """The flags that choose what is assembled: robot, idn, base, grippers and ``--set`` overrides
    (and ``--no-cache`` for commands whose compile the cache can answer)."""
    parser.add_argument("robot", help="registered robot name or spec file")
    parser.add_argument("--idn", type=int, default=0, help="instance number (prefix robot{idn}_)")
    parser.add_argument("--base", help="a registered base instead of the robot's default")
    parser.add_argument("--no-base", action="store_true", help="no base at all")
    parser.add_argument(
        "--gripper",
        action="append",
        default=[],
        metavar="ARM=NAME",
        help="gripper per arm (NAME may be none)",
    )
    parser.add_argument("--no-grippers", action="store_true", help="no grippers on any arm")
    if cached:
        parser.add_argument(
            "--no-cache", action="store_true", help="compile even if the compiled-model cache has this robot"
        )
    add_override_argument(parser)


def add_format_argument(
    parser: argparse.ArgumentParser, formats: Sequence[str] = tuple(REPORT_FORMATS)
) -> None:
    """The ``--format`` flag, text by default, offering only ``formats``."""
    parser.add_argument(
        "--format",
        choices=tuple(formats),
        default="text",
        help="; ".join(f"{name}: {REPORT_FORMATS[name]}" for name in formats),
    )


def image_size(text: str) -> tuple[int, int]:
    """``--size WxH`` as (width, height)."""
    width, sep, height = text.lower().partition("x")
    if not (sep and width.isdigit() and height.isdigit()):
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT in pixels, e.g. 640x480, got '{text}'")
    size = (int(width), int(height))
    if not all(1 <= side <= MAX_SIDE for side in size):
        raise argparse.ArgumentTypeError(f"each side must be 1 to {MAX_SIDE} pixels, got '{text}'")
    return size


GEOM_GROUPS = range(GROUP_COUNT)
"""The geom groups ``render --groups`` takes."""


def geom_groups(text: str) -> tuple[int, ...]:
    """``--groups 0,1,2`` as sorted distinct groups."""
    items = [item.strip() for item in text.split(",") if item.strip()]
    if not items or not all(item.isdigit() and int(item) in GEOM_GROUPS for item in items):
        raise argparse.ArgumentTypeError(
            f"expected geom groups 0 to {GEOM_GROUPS[-1]} separated by commas, e.g. 0,1,2; got '{text}'"
        )
    return tuple(sorted({int(item) for item in items}))


def _output(parser: argparse.ArgumentParser, what: str = "output XML file") -> None:
    parser.add_argument("-o", "--output", help=f"{what} (default: standard output)")


def _list(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "what",
        nargs="?",
        choices=("robots", "bases", "grippers", "motors"),
        default="robots",
        help="what to list (robots)",
    )


def _validate(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("paths", nargs="*", help="spec files or folders (default: the --specs folders)")
    parser.add_argument("--compile", action="store_true", help="also compile each robot with MuJoCo")
    parser.add_argument(
        "--locked",
        action="store_true",
        help="fail when a file robot-assembler.lock lists changed (one line per file, with the robots it "
        "affects); needs no paths",
    )
    add_format_argument(parser, ("text", "github"))


def _lock(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "paths", nargs="*", help="spec files or folders to cover (default: the repository's spec folders)"
    )


def _lint(parser: argparse.ArgumentParser) -> None:
    add_assembly_arguments(parser)
    parser.add_argument(
        "more",
        nargs="*",
        metavar="ROBOT",
        help="more robots, spec files or spec folders (bases and grippers alone)",
    )
    parser.add_argument(
        "--target",
        choices=LINT_TARGETS,
        default="mujoco",
        help="also report what this engine refuses or runs badly: mjwarp (MuJoCo Warp, RA801-803), "
        "mjx (MJX, RA811-815); the engines need not be installed",
    )
    add_format_argument(parser)


def _build(parser: argparse.ArgumentParser) -> None:
    add_assembly_arguments(parser)
    _output(parser)
    parser.add_argument("--bundle", metavar="DIR", help="write the XML and copies of its assets to DIR")
    parser.add_argument(
        "--target",
        choices=BUILD_TARGETS,
        default="mujoco",
        help="mjwarp: also hand the model to MuJoCo Warp's put_model (when installed) before writing",
    )


def _scene(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scene", help="scene YAML file")
    _output(parser)


def _experiment(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("experiment", help="experiment YAML file (kind: experiment)")
    _output(parser)


def _variants(parser: argparse.ArgumentParser) -> None:
    add_assembly_arguments(parser)
    parser.add_argument("-o", "--output", required=True, metavar="DIR", help="folder for the variants")
    parser.add_argument(
        "--grid", action="append", default=[], metavar="PATH=V1,V2", help="values of a field (repeatable)"
    )
    parser.add_argument("--random", type=int, metavar="N", help="N random variants (per grid point)")
    parser.add_argument("--seed", type=int, default=0, help="seed of the random draws (default 0)")
    parser.add_argument(
        "--uniform", action="append", default=[], metavar="PATH=LOW:HIGH", help="uniform draw (repeatable)"
    )
    parser.add_argument(
        "--normal", action="append", default=[], metavar="PATH=MEAN:STD", help="normal draw (repeatable)"
    )
    parser.add_argument(
        "--jobs",
        type=int,
        help="worker processes (default: all cores; one when only joint, actuator, friction or init_qpos "
        "values vary, each written in milliseconds)",
    )
    parser.add_argument(
        "--cache",
        action="store_true",
        help="also keep each variant's compiled model in the cache "
        "(off: a sweep's models are rarely loaded again)",
    )
    sharding = parser.add_mutually_exclusive_group()
    sharding.add_argument(
        "--shard",
        metavar="I/N",
        help="write only the I-th of N slices of the plan (same values and files as the whole run): "
        "one task of a cluster array; then --merge N",
    )
    sharding.add_argument(
        "--merge",
        type=int,
        metavar="N",
        help="check that the N shards in the folder cover the plan exactly once and write its manifest",
    )


def _inspect(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("robot", help="registered robot name or spec file")
    parser.add_argument("--idn", type=int, default=0, help="instance number (prefix robot{idn}_)")
    parser.add_argument(
        "--format", choices=("text", "json"), default="text", help="text: a table (default); json: for tools"
    )
    add_override_argument(parser)


def _schema(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--markdown", action="store_true", help="print the spec reference (docs/spec.md) instead"
    )


def _diff(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("before", help="spec file, registered name or FILE@REV (e.g. specs/x.yaml@HEAD~1)")
    parser.add_argument("after", help="spec file, registered name or FILE@REV")
    parser.add_argument(
        "--format", choices=DIFF_FORMATS, default="text", help="output format (default: text)"
    )
    parser.add_argument(
        "--exit-code", action="store_true", help="exit with 1 when they differ, 0 when not (like git diff)"
    )


def _render(parser: argparse.ArgumentParser) -> None:
    add_assembly_arguments(parser, cached=False)  # a picture compiles the spec it poses
    parser.add_argument("-o", "--output", required=True, help="PNG file to write")
    parser.add_argument(
        "--views",
        default="iso",
        help=f"comma-separated views, tiled in this order: {', '.join(VIEWS)} (default: iso)",
    )
    parser.add_argument(
        "--labels",
        nargs="?",
        const="joints",
        choices=LABELS,
        help="write element names next to them (default when given alone: joints)",
    )
    parser.add_argument(
        "--size",
        type=image_size,
        default=(640, 480),
        metavar="WxH",
        help="size of each view (default 640x480)",
    )
    parser.add_argument(
        "--groups",
        type=geom_groups,
        metavar="G,G",
        help="geom groups to draw, e.g. 0,1,2 (default: each part's visual groups 1 and 2, or its "
        "collision group 0 when it has no visual geoms)",
    )


def _new(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("model_file", help="the vendor's MJCF (.xml) or URDF (.urdf) file; it is not changed")
    parser.add_argument(
        "-o",
        "--output",
        metavar="SPEC",
        help="spec file to write (default: <spec name in snake case>.yaml here)",
    )
    parser.add_argument(
        "--kind",
        choices=("robot", "gripper", "base"),
        help="a robot, a hand, or a mobile base (default: guessed from the names and the wheels)",
    )
    parser.add_argument("--force", action="store_true", help="replace SPEC if it exists")
    parser.add_argument(
        "--pack",
        metavar="DIR",
        help="write the spec into a spec pack at DIR (a pyproject.toml with the entry point, the specs, "
        "the vendor's files copied with their licence) that others pip install",
    )
    parser.add_argument(
        "--strict",
        action="store_true",
        help="refuse a file read only with a repair or with values left out (inertias MuJoCo refuses, "
        "visuals of no size, a <mimic> MuJoCo ignores) instead of writing the repair",
    )


def _cache(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("action", choices=("info", "clear"), help="info: location and size; clear: empty it")


@dataclass(frozen=True)
class Command:
    """A subcommand: its name, what ``--help`` says of it, its arguments, and the module and function
    (taking the parsed ``args``, returning the exit code) that carry it out."""

    name: str
    help: str
    define: Define
    module: str
    function: str
    description: str | None = None
    epilog: str | None = None


COMMANDS: tuple[Command, ...] = (
    Command("list", "registered robots (or bases, grippers)", _list, "assembler.cli.showing", "run_list"),
    Command("validate", "check spec files and folders", _validate, "assembler.cli.checking", "run_validate"),
    Command(
        "lock",
        "write robot-assembler.lock: the sha256 of every file each robot's build reads",
        _lock,
        "assembler.cli.checking",
        "run_lock",
    ),
    Command(
        "lint",
        "report problems MuJoCo accepts silently (codes RA101...)",
        _lint,
        "assembler.cli.checking",
        "run_lint",
    ),
    Command("build", "write a robot's standalone MJCF", _build, "assembler.cli.build", "run_build"),
    Command("scene", "several placed robots in one MJCF", _scene, "assembler.cli.making", "run_scene"),
    Command(
        "experiment",
        "an experiment file's robots, with overrides, in one MJCF",
        _experiment,
        "assembler.cli.making",
        "run_experiment",
    ),
    Command(
        "variants",
        "one MJCF per variant: a grid of values, random draws",
        _variants,
        "assembler.cli.making",
        "run_variants",
    ),
    Command(
        "inspect",
        "joint parameters and actuators, and where each value came from",
        _inspect,
        "assembler.cli.showing",
        "run_inspect",
    ),
    Command(
        "schema",
        "print the JSON Schema of spec files (or --markdown docs)",
        _schema,
        "assembler.cli.checking",
        "run_schema",
    ),
    Command(
        "diff",
        "compare two specs: changed fields and compiled-model differences",
        _diff,
        "assembler.cli.showing",
        "run_diff",
        description="Compare two specs: the fields that changed, and what changed in the compiled "
        "model (robots with their default base and grippers). Each side is a spec file, a registered "
        "name, or FILE@REVISION (read with git show; a parent spec it extends by file path is read "
        "at the same revision, its MJCF from the working tree).",
    ),
    Command(
        "render",
        "write a PNG of the assembled robot in its home pose",
        _render,
        "assembler.cli.making",
        "run_render",
        description="Render the assembled robot in its home pose (keyframe 'home') with MuJoCo's "
        "offscreen renderer, auto-framed, on a floor, one tile per view.",
        epilog="Headless Linux: when MUJOCO_GL is unset and there is no DISPLAY, MUJOCO_GL=egl is "
        "used; set MUJOCO_GL=osmesa for software rendering.",
    ),
    Command(
        "new",
        "write a first spec for a vendor's MJCF or URDF, every guess commented",
        _new,
        "assembler.cli.making",
        "run_new",
        description="Read an MJCF or URDF file as a spec would and write a spec that validates and builds "
        "as written: name, file, joint groups, end-effector, home pose, actuators where the file has none. "
        "Comments mark each guess ('guess:') and what only you can decide ('decide:', with the field to "
        "set); docs/add-your-robot.md explains each. The model file is never changed.",
    ),
    Command("cache", "show or empty the compiled-model cache", _cache, "assembler.cli.build", "run_cache"),
)
"""The subcommands, in the order ``assembler --help`` lists them."""


def build_parser() -> argparse.ArgumentParser:
    """The whole command line: global options, then one subparser per command."""
    parser = argparse.ArgumentParser(
        prog="assembler", description="Assemble MuJoCo robots from declarative YAML specs."
    )
    add_global_options(parser, after_command=False)
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for command in COMMANDS:
        subparser = commands.add_parser(
            command.name, help=command.help, description=command.description, epilog=command.epilog
        )
        command.define(subparser)
        add_global_options(subparser, after_command=True)
        subparser.set_defaults(module=command.module, function=command.function)
    return parser


def parse(argv: Sequence[str] | None = None) -> argparse.Namespace:
    """The command line, with the options given before and after the command joined."""
    args = build_parser().parse_args(argv)
    args.specs = _once([*args.specs, *args.specs_after])
    args.allow_path = _once([*args.allow_path, *args.allow_path_after])
    return args


def _once(paths: Sequence[str]) -> list[str]:
    """``paths`` in order, each folder once (``--specs a --specs ./a/`` reads ``a`` once)."""
    seen: set[str] = set()
    kept = []
    for path in paths:
        where = os.path.realpath(path)
        if where not in seen:
            seen.add(where)
            kept.append(path)
    return kept
