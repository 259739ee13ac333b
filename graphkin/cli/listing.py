"""``graphkin list``: the catalog of textbook problems and flywheels."""

from __future__ import annotations


def add_parser(sub) -> None:
    """Add ``list`` to the ``graphkin`` subcommands."""
    sub.add_parser("list", help="list the catalog problems")


def run(args) -> int:
    """Carry out ``graphkin list``: the catalog's problems with their family and source, then its flywheels."""
    from graphkin import catalog
    from graphkin.cycle.flywheel_file import load_flywheel

    names, flywheels = catalog.names(), catalog.flywheel_names()
    # One column for every name, two spaces past the longest, so that no name runs into its title.
    w = max(map(len, [*names, *flywheels]), default=0) + 2
    for name in names:
        problem = catalog.load(name)
        print(f"{name:<{w}}{problem.title}")
        print(f"{'':<{w}}family: {catalog.family(name)}")
        print(f"{'':<{w}}{problem.source}")
    print("\nflywheels (graphkin flywheel NAME):")
    for name in flywheels:
        fly = load_flywheel(catalog.flywheel_path(name), name=name)
        print(f"{name:<{w}}{fly.title}")
        print(f"{'':<{w}}{fly.source}")
    return 0
