"""YAML text -> validated spec: the schema (:mod:`.schema`, pydantic only), documents read with
positions, inheritance and overrides (:mod:`.documents`), spec files and folders (:mod:`.spec_files`)
and the one spelling of a field's place in a document (:mod:`.fieldpath`)."""
