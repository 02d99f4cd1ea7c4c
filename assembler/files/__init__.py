"""Files in and out: where files are and which may be read (:mod:`.paths`, :mod:`.repositories`),
bounds on untrusted input (:mod:`.limits`), what to install for a package (:mod:`.extras`),
writing the user's outputs (:mod:`.writing`), and settings held in environment variables changed
for a block (:mod:`.variables`)."""
