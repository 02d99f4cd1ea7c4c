"""Check a part's MJCF file as MuJoCo checks it, before anything of it is attached.

``MjSpec.attach`` silently drops what it cannot resolve: an actuator on a joint that does not exist,
a sensor of a missing site, a tendon through a missing joint, an equality, contact pair or exclude
naming a missing body or geom, a skin bone... MuJoCo compiling the file itself refuses every one of
them (and so does ``MjSpec.copy()``: the check compiles a spec freshly parsed, never a copy). So each
file is compiled once on its own, as MuJoCo would (after its declared ``mjcf_fixes``,
asset paths absolute), and a refusal becomes one located problem (:mod:`assembler.mjcf.refusal`).
The check runs once per file version: :func:`assembler.mjcf.source.load_mjcf` caches its result.

Two departures from compiling the file as it is, each chosen on purpose:

- **Cost.** Decoding meshes and textures is most of a compile: the first compile of robosuite's
  Panda or GR1 takes about a second, which a robot read from the compiled-model cache would
  otherwise pay on every load. The probe replaces each file-backed mesh by a tetrahedron, each
  file-backed texture by a 2x2 flat one and each file-backed height field by a 2x2 flat one,
  keeping names, kinds and everything that refers to them: every reference MuJoCo checks is still
  checked, for a few milliseconds (measured: ~3 ms to compile the probe of Panda or GR1, plus a
  second parse of the file). Skin files are read, since they name bodies. What the probe no longer
  sees is the contents of the other files (a mesh of zero volume, say); the assembly's own compile
  reads them and refuses such a file, so nothing is dropped in silence.
- **Mass.** A part may be valid only with what the assembly puts on it: robosuite's NullMobileBase
  has a massless moving support that the robot standing on it weighs down (MuJoCo alone says "mass
  and inertia of moving bodies must be larger than mjMINVAL"). The probe raises the compiler's
  ``boundmass``/``boundinertia`` to a tiny floor, so a massless body passes here and is judged by
  the assembly's compile, where it still fails loudly if nothing gives it mass.
"""

from __future__ import annotations

import mujoco

from assembler.errors import MjcfError
from assembler.mjcf import mujoco_warnings
from assembler.mjcf.asset_names import name_assets_after_files
from assembler.mjcf.refusal import LineMap, refusal_line

TETRAHEDRON: tuple[float, ...] = (0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1)
"""Vertices of the stand-in mesh: positive volume at any scale a mesh is given (1e-3 -> 1.7e-10 m^3)."""

MASS_FLOOR = 1e-6
"""kg, and kg m^2 for inertia: well above MuJoCo's mjMINVAL (1e-15), negligible next to any real part."""


def _stand_in_assets(spec: mujoco.MjSpec, resolved: mujoco.MjSpec) -> None:
    """Replace the contents of file-backed meshes, textures and height fields (names stay); skins
    keep their files, which name bones, read from the paths already resolved in ``resolved``. An
    unnamed asset first takes its file's name, as MuJoCo would have given it from the file."""
    name_assets_after_files(spec)
    spec.meshdir = spec.texturedir = ""
    for skin, same in zip(spec.skins, resolved.skins, strict=True):
        skin.file = same.file
    for mesh in spec.meshes:
        if mesh.file:
            mesh.file = ""
            mesh.content_type = ""
            mesh.uservert = list(TETRAHEDRON)
    for texture in spec.textures:
        if texture.file or any(texture.cubefiles):
            texture.file = ""
            texture.content_type = ""
            texture.cubefiles = [""] * 6
            texture.builtin = mujoco.mjtBuiltin.mjBUILTIN_FLAT
            texture.width = texture.height = 2
    for hfield in spec.hfields:
        if hfield.file:
            hfield.file = ""
            hfield.content_type = ""
            hfield.nrow = hfield.ncol = 2
            hfield.userdata = [0.0] * 4


def check_as_mujoco(probe: mujoco.MjSpec, resolved: mujoco.MjSpec, shown: str, lines: LineMap) -> None:
    """Refuse the file (displayed as ``shown``) if MuJoCo refuses to compile it; ``lines`` maps
    MuJoCo's line numbers to the file's.

    ``probe`` must come straight from parsing the file and is used up: its assets are replaced.
    Not a copy of a spec: ``MjSpec.copy()`` drops what it cannot resolve, as ``attach`` does.
    ``resolved`` is another parse of the same file whose asset paths are already absolute and confined.
    """
    _stand_in_assets(probe, resolved)
    probe.compiler.boundmass = max(probe.compiler.boundmass, MASS_FLOOR)
    probe.compiler.boundinertia = max(probe.compiler.boundinertia, MASS_FLOOR)
    try:
        # Its warnings are about stand-ins, or come again from the part's real compile: not shown.
        with mujoco_warnings.collected():
            probe.compile()
    except ValueError as error:
        raise MjcfError(refusal_line(str(error), shown, lines, "MuJoCo refuses it")) from None
