"""``graphkin list``: the catalog of textbook problems and flywheels."""

from __future__ import annotations


def add_parser(sub) -> None:
    """Add ``list`` to the ``graphkin`` subcommands."""
    sub.add_parser("list", help="list the catalog problems")


def run(args) -> int:
    """Carry out ``graphkin list``: the catalog's problems with their family and source, then its flywheels."""
    from graphkin import catalog

    for name in catalog.names():
        problem = catalog.load(name)
        print(f"{name:<24}{problem.title}")
        print(f"{'':<24}family: {catalog.family(name)}")
        print(f"{'':<24}{problem.source}")
    print("\nflywheels (graphkin flywheel NAME):")
    for name in catalog.flywheel_names():
        from graphkin.cycle.flywheel_file import load_flywheel

        fly = load_flywheel(catalog.flywheel_path(name), name=name)
        print(f"{name:<24}{fly.title}")
        print(f"{'':<24}{fly.source}")
    return 0
