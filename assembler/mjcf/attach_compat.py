"""What ``MjSpec.attach`` misses on the older MuJoCo releases we support, put right or refused.

Each rule names the release that fixed MuJoCo's behaviour; on that release and later it does
nothing. Before 3.16, attaching a part with a prefix left its tendons' material references and its
skins' names unprefixed (the compile then fails, or names collide between parts). Before 3.17, the
bones a skin *file* names are not prefixed either, and the file cannot be rewritten: such a part is
refused when it is read, with what to do. On 3.9 (4.0 is right; the releases between are not tested),
a part whose defaults give sites a material (dm-control's Kinova ``common.xml``:
``<default><site material="red"/>``) cannot be compiled once attached with a prefix ("material 'red'
not found in site 0"), whatever its sites say: the part is re-read without those default materials,
its sites keeping the materials the defaults gave them.
"""

from __future__ import annotations

import mujoco

from assembler.errors import MjcfError
from assembler.files.paths import display_path
from assembler.mjcf.emit import to_xml
from assembler.mjcf.versions import mujoco_at_least

PREFIXES_TENDON_MATERIALS_AND_SKINS = (3, 16)
PREFIXES_SKIN_FILE_BONES = (3, 17)
ATTACHES_DEFAULT_SITE_MATERIALS = (4, 0)


def refuse_unattachable(part: mujoco.MjSpec, shown: str) -> None:
    """A part MuJoCo's attach would break on this release: a skin whose bones come from its file."""
    if mujoco_at_least(*PREFIXES_SKIN_FILE_BONES):
        return
    for skin in part.skins:
        if skin.file:
            release = ".".join(map(str, PREFIXES_SKIN_FILE_BONES))
            raise MjcfError(
                f"{shown}: skin '{skin.name}' reads its bones from {display_path(skin.file)}, which MuJoCo "
                f"{mujoco.__version__} cannot rename when it attaches the part (fixed in {release}): "
                f"write the skin's vertices and bones in the MJCF, or install mujoco>={release}"
            )


def prefix_what_attach_misses(part: mujoco.MjSpec, prefix: str) -> None:
    """Give ``part``'s tendon materials and skin names the prefix before it is attached with it, on
    releases whose attach leaves them as they are (an attached spec's elements cannot be edited
    through the assembly afterwards: the attach is by reference)."""
    if mujoco_at_least(*PREFIXES_TENDON_MATERIALS_AND_SKINS):
        return
    for tendon in part.tendons:
        if tendon.material:
            tendon.material = prefix + tendon.material
    for skin in part.skins:
        if skin.name:
            skin.name = prefix + skin.name


def settle_default_site_materials(part: mujoco.MjSpec) -> mujoco.MjSpec:
    """``part``, or on releases whose attach breaks on a default site material, the same model re-read
    from MuJoCo's own XML of it with the defaults' site materials moved onto the sites (which already
    hold them). Only a re-read clears what the defaults left behind: editing the defaults in place or
    copying the spec does not. Asset paths must already be absolute."""
    if mujoco_at_least(*ATTACHES_DEFAULT_SITE_MATERIALS):
        return part
    defaults = [part.default, *(site.classname for site in part.sites)]
    with_material = [default for default in defaults if default.site.material]
    if not with_material:
        return part
    for default in with_material:
        default.site.material = ""
    return mujoco.MjSpec.from_string(to_xml(part))  # every digit: MuJoCo's writer keeps six
