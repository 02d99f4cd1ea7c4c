"""Names -> classes -> instances: the registries (:mod:`.lookup`), specs registered as classes
(:mod:`.catalog`), when two files are one spec (:mod:`.same_spec`), the names a spec gives that must
be registered (:mod:`.references`), and instances made by name (:mod:`.instances`)."""
