"""The corpus of issue 24: published robots read from their installed packages, given specs by
``assembler new``, compared with MuJoCo's own load of the vendor's files (``pip install ".[corpus]"``)."""
