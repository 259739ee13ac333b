"""The explorer's thread: a message from the browser that ipykernel hands to another thread is answered on the
explorer's own (the kernel's main thread), never alongside what that thread is drawing."""

from __future__ import annotations

import functools
import threading


def running_loop():
    """The event loop a kernel dispatches messages from, or None (plain Python, a test)."""
    import asyncio

    try:
        return asyncio.get_running_loop()
    except RuntimeError:
        return None


def answers_the_browser(name: str, what: str, trait: str = "value"):
    """Decorate the observer of the control ``name`` (``what`` it holds, for people; its ``trait`` observed).

    The observer is called as ``observer(self, change, by_browser)``, where
    ``by_browser`` tells a value the browser sent from one that code set
    (ipywidgets locks the property while it applies a browser's value: the lock
    is read here, while it is held).

    The explorer belongs to the thread it was made in, the kernel's main thread:
    its figure, its timers and its drawing ahead are never touched from two
    threads. ipykernel 7 may run a comm message's handler on another thread (a
    subshell's: a comm's messages go to the subshell that last sent on it),
    where it would close or step a drawing that the main thread is stepping. On
    another thread, the observer's work is handed to the main thread's event
    loop, and the handler returns at once.

    An error in answering the browser is shown in the status line: run from a
    comm message, outside any cell, it would otherwise reach only the kernel's
    log, and the explorer would silently stop answering. A value set by code
    on the explorer's own thread raises in the cell that set it.
    """

    def decorate(observer):
        @functools.wraps(observer)
        def observe(self, change):
            by_browser = trait in getattr(self, name)._property_lock
            home = self._home_loop if threading.get_ident() != self._home else None
            if home is not None and home.is_running():
                home.call_soon_threadsafe(self._answer, observer, change, by_browser, what, True)
            else:
                self._answer(observer, change, by_browser, what, False)

        return observe

    return decorate
