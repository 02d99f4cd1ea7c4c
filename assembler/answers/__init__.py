"""The one path answering a request: a request made before is answered from its record in the cache
without reading a spec (:mod:`.records`; ``load_model``'s fast path :mod:`.load_model`, the robots
``assemble`` hands out :mod:`.deferred`, ``assembler build``'s :mod:`.build_request`), anything else
is resolved through the registry and compiled (:mod:`.request`), then recorded."""
