"""Fixtures the exercise tests share."""

import pytest


@pytest.fixture()
def kernel(tmp_path, monkeypatch):
    """A fresh IPython shell as the student's kernel (its history in memory only), started in the notebook's folder
    (``tmp_path``)."""
    from IPython.core.interactiveshell import InteractiveShell
    from traitlets.config import Config

    monkeypatch.setenv("IPYTHONDIR", str(tmp_path / "ipython"))
    monkeypatch.chdir(tmp_path)
    config = Config()
    config.HistoryManager.enabled = False
    InteractiveShell.clear_instance()
    shell = InteractiveShell.instance(config=config)
    yield shell
    InteractiveShell.clear_instance()
