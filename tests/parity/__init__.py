"""robosuite as the oracle of our assemblies: robosuite's side of each case (``robosuite_side``), the
pairing of elements across two models (``keys``), the field-by-field comparison (``oracle``), the
cases with their documented deviations (``cases``) and the generated parity document (``report``).
It needs robosuite installed (``pip install ".[test,robosuite]"``).
"""
