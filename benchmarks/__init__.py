"""Benchmarks: robot-assembler measured side by side with robosuite and MuJoCo.

Run ``python -m benchmarks`` from the repository root (``--quick`` for a smoke run); it prints each
figure as a ratio against its reference and writes ``benchmarks/results.json`` and
``benchmarks/results.md``. See :mod:`benchmarks.run`.
"""
