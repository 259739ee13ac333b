"""The one build step pyproject.toml cannot declare: the lesson notebooks into the wheel, for ``graphkin lessons``.

The lessons live in ``lessons/`` at the repository's root (the docs site, the tests and JupyterLab read them
there); package data can only come from inside a package's folder. So the wheel's build copies
``lessons/NN_name.ipynb`` to ``graphkin/lessons/`` (the sdist carries them: MANIFEST.in). An editable install
copies nothing: ``graphkin.catalog.lessons`` reads ``lessons/`` in the clone.
"""

from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py


class BuildPyWithLessons(build_py):
    def run(self):
        super().run()
        if self.editable_mode:
            return
        target = Path(self.build_lib) / "graphkin" / "lessons"
        self.mkpath(str(target))
        for notebook in sorted(Path(__file__).parent.glob("lessons/[0-9][0-9]_*.ipynb")):
            self.copy_file(str(notebook), str(target / notebook.name))


setup(cmdclass={"build_py": BuildPyWithLessons})
