"""A compiled model or its MJCF changed without a compile: which spec fields a patch can carry
(:mod:`.patchable`), the tables it compares (:mod:`.resolved`), a robot with overrides answered from
its plain robot's cached model (:mod:`.robot_variant`) or XML (:mod:`.xml_edits`), the constants a
patch must recompute (:mod:`.derived`), variant files written from one compile
(:mod:`.variant_files`), and which overrides changed nothing (:mod:`.override_effects`)."""
