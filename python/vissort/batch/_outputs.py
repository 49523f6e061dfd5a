"""Never overwrite an input: a batch's outputs compared, before any work, with the files it
reads and with each other, and its own files written whole or not at all. The command line's
rules (docs/cli.md, "Inputs are never overwritten"), from the library itself
(output_files.h, atomic_file.h)."""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Callable, Dict, Iterable, List, Optional, Sequence, Set

from vissort import _vissort


@dataclass(frozen=True)
class FileUse:
    """A file read or written, named as the user knows it. frames: for a frame pattern
    (out/frame_%04d.png), the frame numbers it names; None for a plain path."""

    what: str
    path: str
    frames: Optional[range] = None


def check(inputs: Iterable[FileUse], outputs: Sequence[FileUse]) -> None:
    """ValueError, one line naming both uses and the path, when an output is an input or
    another output (OutputFiles, output_files.h)."""
    clash = _vissort._output_clash(
        [(i.what, i.path) for i in inputs],
        [(o.what, o.path, o.frames.start if o.frames else 0, len(o.frames) if o.frames else 0)
         for o in outputs])
    if clash:
        raise ValueError(clash)


def scene_inputs(scene: object, spec: str) -> List[FileUse]:
    """The files a batch's scene reads: a loaded Scene's source_files, else its path (a
    builtin reads none)."""
    files = getattr(scene, "source_files", None)
    if files is not None:
        return [FileUse("a file the scene read", f) for f in files]
    if spec.startswith("builtin:"):
        return []
    return [FileUse("the scene file", spec)]


def write_whole(path: str, write: Callable[[str], None]) -> None:
    """Calls write(temporary path) beside path and renames the file it wrote onto path: a failed
    or killed writer leaves the old file whole (writeFileAtomically, atomic_file.h)."""
    _vissort._write_file_atomically(path, write)


def remove_leftovers(pattern: str, frames: range) -> None:
    """Removes the temporary files that writers killed mid-frame left beside the pattern's
    frames (.NAME.vissort-XXXXXXXX.partial): once a batch's tasks are over, so that no running
    writer's file is taken. One listing of each frame folder."""
    names: Dict[str, Set[str]] = {}
    for f in frames:
        folder, name = os.path.split(pattern % f)
        names.setdefault(folder or ".", set()).add(name)
    for folder, frame_names in names.items():
        with os.scandir(folder) as entries:
            for entry in entries:
                stem, marker, _ = entry.name.rpartition(".vissort-")
                if (marker and entry.name.endswith(".partial") and stem.startswith(".")
                        and stem[1:] in frame_names):
                    try:
                        os.remove(entry.path)
                    except FileNotFoundError:
                        pass
