"""What the commands do, without argument parsing: validate (:mod:`.validate`), lint (:mod:`.lint`),
diff (:mod:`.diff`) and render (:mod:`.render`)."""
