"""From a request to a compiled model: ``load_model``'s fast path (:mod:`.load_model`), its slow
path through the registry (:mod:`.request`), and which overrides changed nothing
(:mod:`.override_effects`)."""
