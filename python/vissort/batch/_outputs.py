"""Never overwrite an input: a batch's outputs compared, before any work, with the files it
reads and with each other (the command line's rule: docs/cli.md, "Outputs"), and its own files
written whole or not at all."""

from __future__ import annotations

import contextlib
import os
import stat
import tempfile
from dataclasses import dataclass
from typing import Callable, Iterable, List, Optional, Sequence


_FRAMES_STATTED = 4096


@dataclass(frozen=True)
class FileUse:
    """A file read or written, named as the user knows it. frames: for a frame pattern
    (out/frame_%04d.png), the frame numbers it names; None for a plain path."""

    what: str
    path: str
    frames: Optional[range] = None


def _special(path: str) -> bool:
    """There and not a regular file or folder (/dev/null, a FIFO): writing replaces nothing."""
    try:
        mode = os.stat(path).st_mode
    except OSError:
        return False
    return not stat.S_ISREG(mode) and not stat.S_ISDIR(mode)


def _same(a: str, b: str) -> bool:
    a_there, b_there = os.path.exists(a), os.path.exists(b)
    if a_there and b_there:
        return os.path.samefile(a, b)
    return not a_there and not b_there and os.path.realpath(a) == os.path.realpath(b)


def _names(use: FileUse) -> List[str]:
    """The resolved path of every file the use names: a pattern's folder resolved once when
    the frame field is in the file name."""
    if use.frames is None:
        return [use.path]
    folder, name = os.path.split(use.path)
    if "%" in name:
        where = os.path.realpath(folder or ".")
        return [os.path.join(where, name % f) for f in use.frames]
    return [os.path.realpath(use.path % f) for f in use.frames]


def _shared(a: FileUse, b: FileUse) -> Optional[str]:
    """A file both uses name, or None."""
    if a.frames is None and b.frames is None:
        return a.path if not _special(a.path) and _same(a.path, b.path) else None
    if a.frames is not None and b.frames is not None:
        theirs = set(_names(b))
        return next((n for n in _names(a) if n in theirs), None)
    pattern, plain = (a, b) if a.frames is not None else (b, a)
    if _special(plain.path):
        return None
    target = os.path.realpath(plain.path)
    names = _names(pattern)
    if target in names:
        return target
    # A frame file that is a link to the plain file: each existing frame compared as a file,
    # up to _FRAMES_STATTED frames (a pattern of 100,000 is checked by name alone).
    if os.path.exists(plain.path) and len(names) <= _FRAMES_STATTED:
        for name in names:
            if os.path.exists(name) and os.path.samefile(name, plain.path):
                return name
    return None


def check(inputs: Iterable[FileUse], outputs: Sequence[FileUse]) -> None:
    """ValueError, one line naming both uses and the path, when an output is an input or
    another output (the same file by device and inode, or the same resolved path)."""
    written = [o for o in outputs if o.path not in ("", "-")]
    read = [i for i in inputs if i.path]
    for output in written:
        for source in read:
            shared = _shared(output, source)
            if shared is not None:
                raise ValueError(f"{output.what} '{output.path}' is {source.what} "
                                 f"'{source.path}' ({shared}): vissort never overwrites an "
                                 "input; choose another path")
    for i, first in enumerate(written):
        for second in written[i + 1:]:
            shared = _shared(first, second)
            if shared is not None:
                raise ValueError(f"{first.what} '{first.path}' and {second.what} "
                                 f"'{second.path}' are one file ({shared}): give each output "
                                 "its own path")


def scene_inputs(scene: object, spec: str) -> List[FileUse]:
    """The files a batch's scene reads: a loaded Scene's source_files, else its path (a
    builtin reads none)."""
    files = getattr(scene, "source_files", None)
    if files is not None:
        return [FileUse("a file the scene read", f) for f in files]
    if spec.startswith("builtin:"):
        return []
    return [FileUse("the scene file", spec)]


def write_whole(path: str, write: Callable[[str], None], suffix: str = "") -> None:
    """Writes path through write(temporary path) in the same folder, renamed over path once
    complete: a failed or killed writer leaves the old file whole. Special files (/dev/null)
    are written in place."""
    if _special(path):
        write(path)
        return
    target = os.path.realpath(path)  # a link's file is replaced, the link stays
    folder, name = os.path.split(target)
    handle, partial = tempfile.mkstemp(prefix=f".{name[:200]}.vissort-", suffix=f".partial{suffix}",
                                       dir=folder)
    os.close(handle)
    try:
        write(partial)
        with contextlib.suppress(OSError):
            if os.path.exists(target):
                os.chmod(partial, stat.S_IMODE(os.stat(target).st_mode))
            else:
                umask = os.umask(0)
                os.umask(umask)
                os.chmod(partial, 0o666 & ~umask)
        os.replace(partial, target)
    finally:
        with contextlib.suppress(FileNotFoundError):
            os.remove(partial)
