"""The one bounded read: a stranger's file costs no more than its reader's limit, a file at the limit
is read whole, and a FIFO is refused at once instead of waited on."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from assembler.files.regular import FileTooLarge, NotARegularFile, read_bounded


def test_a_file_at_the_limit_is_read_whole(tmp_path: Path) -> None:
    path = tmp_path / "spec.yaml"
    path.write_bytes(b"x" * 64)
    assert read_bounded(path, 64) == b"x" * 64


def test_a_file_one_byte_over_the_limit_is_refused_with_the_limit_named(tmp_path: Path) -> None:
    path = tmp_path / "spec.yaml"
    path.write_bytes(b"x" * 65)
    with pytest.raises(FileTooLarge) as raised:
        read_bounded(path, 64)
    assert raised.value.strerror == "the file's size exceeds the limit of 64 bytes"
    assert raised.value.filename == str(path)


def test_a_fifo_is_refused_without_waiting_for_a_writer(tmp_path: Path) -> None:
    fifo = tmp_path / "robot.xml"
    os.mkfifo(fifo)
    with pytest.raises(NotARegularFile) as raised:
        read_bounded(fifo, 64)
    assert "FIFO" in str(raised.value.strerror)


def test_a_missing_file_is_the_os_error_open_raises(tmp_path: Path) -> None:
    with pytest.raises(FileNotFoundError):
        read_bounded(tmp_path / "absent.yaml", 64)
