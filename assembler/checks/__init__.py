"""What a lint check is: a :class:`~.finding.Finding` (code, severity, where, what to do) about a
:class:`~.target.LintTarget` (a built part and its spec). The checks themselves live with what they
know: the core's in :mod:`assembler.tools.lint`, robosuite's in :mod:`assembler.robosuite.checks`,
MuJoCo Warp's and MJX's in :mod:`assembler.gpu.warp_checks` and :mod:`assembler.gpu.mjx_checks`."""
