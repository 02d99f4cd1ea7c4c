"""Several robots or many robots: scenes (:mod:`.scene`), experiments (:mod:`.experiment`) and
variants of one robot (:mod:`.variants`)."""
