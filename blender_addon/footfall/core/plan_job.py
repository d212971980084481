# SPDX-License-Identifier: GPL-3.0-or-later
"""Planning on a thread of its own, so that Blender's interface stays live:
the core plans without Python's lock on its own threads; this thread only
waits for it. The progress can be read and the run cancelled at any time;
nothing is stored here (the caller stores the plan when it is done)."""

import threading
import time
from typing import Optional, Sequence

from . import native
from .scenario import plan, replan


class PlanJob:
    """Plans `document` (or, with `fixed` and `names`, those agents again
    among the others' plans in `fixed`) on `threads` threads."""

    def __init__(self, document: dict, threads: int, fixed=None, names: Optional[Sequence[str]] = None,
                 source: str = "scene"):
        self.progress = 0.0  # share of the agents planned
        self._cancel = native.load().CancelFlag()
        self._plan = None
        self._error: Optional[BaseException] = None
        self._started = time.perf_counter()
        self.seconds = 0.0  # planning time, once done

        def run():
            try:
                if names is None:
                    self._plan = plan(document, source, progress=self._note, cancel=self._cancel, threads=threads)
                else:
                    self._plan = replan(document, fixed, names, source, progress=self._note, cancel=self._cancel,
                                        threads=threads)
            except BaseException as error:  # handed to the caller's thread by result()
                self._error = error
            self.seconds = time.perf_counter() - self._started

        self._thread = threading.Thread(target=run, name="footfall plan", daemon=True)
        self._thread.start()

    def _note(self, fraction: float) -> None:
        self.progress = fraction

    @property
    def done(self) -> bool:
        return not self._thread.is_alive()

    def cancel(self) -> None:
        """Asks the core to stop; it does within a step or two."""
        self._cancel.set()

    @property
    def cancelled(self) -> bool:
        return self._cancel.is_set()

    def result(self):
        """Waits for the run to end; returns the native Plan, or raises what
        the run raised (ValueError naming the field at fault)."""
        self._thread.join()
        if self._error is not None:
            raise self._error
        return self._plan
