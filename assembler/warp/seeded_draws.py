"""A plan's uniform draws for many worlds at once, the very numbers ``default_rng([seed, i])`` draws.

A plan draws world i's values from its own generator, ``numpy.random.default_rng([seed, i])``, so
that a world's values depend on the seed and its index only (:mod:`assembler.worlds.variants.plan`).
Making 4,096 generators costs ~80 ms, most of a batch's CPU time; this module runs the same
algorithms over arrays instead: numpy's ``SeedSequence`` (its entropy pool of four 32-bit words and
``generate_state``), ``PCG64`` seeded from it (128-bit state, XSL-RR output) and ``Generator.uniform``
(``low + (high - low) * (next_uint64 >> 11) * 2^-53``). A test compares them with numpy's own.
Normal draws (numpy's ziggurat) and seeds or indices of 2^32 and over are left to the generators.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from assembler.worlds.variants.plan import Draw, VariantPlan

U32 = np.uint64(0xFFFFFFFF)
INIT_A, MULT_A, INIT_B, MULT_B = 0x43B0D7E5, 0x931E8875, 0x8B51F9DD, 0x58F38DED
MIX_MULT_L, MIX_MULT_R = 0xCA01F9DD, 0x4973F715
PCG_MULTIPLIER = (2549297995355413924, 4865540595714422341)
"""numpy's constants: ``bit_generator.pyx`` (SeedSequence) and ``pcg64.h`` (the 128-bit multiplier)."""


def _u32(values: NDArray[np.uint64]) -> NDArray[np.uint64]:
    return values & U32


def _pool(seed: int, indices: NDArray[np.uint64]) -> list[NDArray[np.uint64]]:
    """SeedSequence([seed, index]).pool, four 32-bit words per index (held in uint64 arrays)."""
    constant = INIT_A

    def hashmix(value: NDArray[np.uint64]) -> NDArray[np.uint64]:
        nonlocal constant
        value = value ^ np.uint64(constant)
        constant = (constant * MULT_A) & 0xFFFFFFFF
        value = _u32(value * np.uint64(constant))
        return value ^ (value >> np.uint64(16))

    def mix(x: NDArray[np.uint64], y: NDArray[np.uint64]) -> NDArray[np.uint64]:
        result = _u32(np.uint64(MIX_MULT_L) * x - np.uint64(MIX_MULT_R) * y)
        return result ^ (result >> np.uint64(16))

    entropy = [np.full_like(indices, seed), indices]
    pool = [hashmix(entropy[i] if i < len(entropy) else np.zeros_like(indices)) for i in range(4)]
    for source in range(4):
        for target in range(4):
            if source != target:
                pool[target] = mix(pool[target], hashmix(pool[source]))
    return pool


def _state_words(pool: list[NDArray[np.uint64]]) -> list[NDArray[np.uint64]]:
    """``generate_state(4, np.uint64)``: eight 32-bit words, paired little-endian into four."""
    constant, words = INIT_B, []
    for i in range(8):
        value = pool[i % 4] ^ np.uint64(constant)
        constant = (constant * MULT_B) & 0xFFFFFFFF
        value = _u32(value * np.uint64(constant))
        words.append(value ^ (value >> np.uint64(16)))
    return [words[2 * k] | (words[2 * k + 1] << np.uint64(32)) for k in range(4)]


def _multiply(a: NDArray[np.uint64], b: int) -> tuple[NDArray[np.uint64], NDArray[np.uint64]]:
    """The 128-bit product of uint64 ``a`` and the constant ``b``: (high, low) words."""
    a0, a1 = a & U32, a >> np.uint64(32)
    b0, b1 = np.uint64(b & 0xFFFFFFFF), np.uint64(b >> 32)
    p00, p01, p10, p11 = a0 * b0, a0 * b1, a1 * b0, a1 * b1
    middle = (p00 >> np.uint64(32)) + (p01 & U32) + (p10 & U32)
    low = (p00 & U32) | (middle << np.uint64(32))
    high = p11 + (p01 >> np.uint64(32)) + (p10 >> np.uint64(32)) + (middle >> np.uint64(32))
    return high, low


def _step(
    hi: NDArray[np.uint64], lo: NDArray[np.uint64], inc: tuple[NDArray[np.uint64], NDArray[np.uint64]]
) -> tuple[NDArray[np.uint64], NDArray[np.uint64]]:
    """PCG's step: state * multiplier + inc, modulo 2^128."""
    high, low = _multiply(lo, PCG_MULTIPLIER[1])
    high = high + hi * np.uint64(PCG_MULTIPLIER[1]) + lo * np.uint64(PCG_MULTIPLIER[0])
    added = low + inc[1]
    return high + inc[0] + (added < low).astype(np.uint64), added


def uniform_columns(seed: int, indices: Sequence[int], draws: Sequence[Draw]) -> NDArray[np.float64] | None:
    """Row k: ``draws[k].sample(rng)`` for every index, rng = ``default_rng([seed, index])`` drawing the
    draws in order; None when a draw is normal or a number is 2^32 or over (see the module)."""
    index = np.asarray(indices, dtype=np.uint64)
    if any(d.law != "uniform" for d in draws) or not 0 <= seed < 2**32 or (index >= 2**32).any():
        return None
    with np.errstate(over="ignore"):
        s0, s1, i0, i1 = _state_words(_pool(seed, index))
        inc = ((i0 << np.uint64(1)) | (i1 >> np.uint64(63)), (i1 << np.uint64(1)) | np.uint64(1))
        zero = np.zeros_like(index)
        hi, lo = _step(zero, zero, inc)
        added = lo + s1
        hi, lo = hi + s0 + (added < lo).astype(np.uint64), added
        hi, lo = _step(hi, lo, inc)
        out = np.empty((len(draws), len(index)))
        for row, draw in enumerate(draws):
            hi, lo = _step(hi, lo, inc)
            mixed, rotation = hi ^ lo, hi >> np.uint64(58)
            value = (mixed >> rotation) | (mixed << ((np.uint64(64) - rotation) & np.uint64(63)))
            unit = (value >> np.uint64(11)).astype(np.float64) * (1.0 / 9007199254740992.0)
            out[row] = draw.a + (draw.b - draw.a) * unit
    return out


def plan_columns(
    plan: VariantPlan, indices: Sequence[int]
) -> tuple[dict[str, NDArray[np.int64]], dict[str, NDArray[np.float64]]]:
    """:meth:`VariantPlan.columns`, its uniform draws computed over arrays when it has no other."""
    drawn = uniform_columns(plan.seed, indices, plan.draws) if plan.draws else None
    if drawn is None:
        return plan.columns(indices)
    return plan.positions(indices), {draw.key: drawn[row] for row, draw in enumerate(plan.draws)}
