"""A roster on several workers gives what one process gives; classmates who drew the same values share a draw."""

from __future__ import annotations

from graphkin import exercises
from graphkin.exercises import variants
from graphkin.exercises.batch import PARALLEL_FROM, run_roster
from graphkin.exercises.variants import draw_shard, make_variant

NAME = "single_link"  # the cheapest exercise: 7 × 13 draws, so a class of 200 shares most of them
STUDENTS = [f"s{i:04d}" for i in range(PARALLEL_FROM)]
SECRET = "batch-secret"


def _values(v) -> tuple:
    return tuple(g.value for g in v.data)


def test_two_workers_give_what_one_process_gives_in_roster_order():
    ex = exercises.load(NAME)
    keys = {w: run_roster(ex, "key", STUDENTS, SECRET, workers=w) for w in (1, 2)}
    assert keys[1] == keys[2]
    assert [k["student"] for k in keys[2]] == STUDENTS
    # A wrong answer for some students: graded alike on both, and each report is that student's.
    answers = [{q["id"]: ("1 N" if i % 3 == 0 else q["answer"]["text"]) for q in k["questions"]}
               for i, k in enumerate(keys[1])]
    grades = {w: run_roster(ex, "grade", STUDENTS, SECRET, answers=answers, workers=w) for w in (1, 2)}
    assert grades[1] == grades[2]
    full = [g["score"] == g["max"] for g in grades[2]]
    assert full == [i % 3 != 0 for i in range(len(STUDENTS))]


def test_classmates_with_the_same_values_share_one_solved_draw():
    ex = exercises.load(NAME)
    variants._DRAWS.clear()
    made = [make_variant(ex, s, SECRET) for s in STUDENTS]
    by_values: dict = {}
    for v in made:
        by_values.setdefault(_values(v), []).append(v)
    shared = [vs for vs in by_values.values() if len(vs) > 1]
    assert shared, "200 students over 91 draws must share some"
    for vs in shared:
        assert all(v.solved is vs[0].solved for v in vs)
        # The same answers, each on its own student's sheet.
        texts = [[q["answer"]["text"] for q in v.key()["questions"]] for v in vs]
        assert all(t == texts[0] for t in texts)
        assert [v.key()["student"] for v in vs] == [v.student for v in vs]
    # Solved once per distinct draw, not once per student.
    assert len({id(v.solved) for v in made}) == len(by_values)


def test_the_shard_follows_the_first_draw():
    ex = exercises.load(NAME)
    for shards in (2, 3):
        seen: dict = {}
        for s in STUDENTS:
            k = draw_shard(ex, s, SECRET, shards)
            assert 0 <= k < shards and k == draw_shard(ex, s, SECRET, shards)
            first = tuple(g.value for g in variants._choose(ex, s, SECRET, 0))
            assert seen.setdefault(first, k) == k
        assert len(set(seen.values())) == shards  # every worker gets some
    # An id that cannot be read goes to the first worker, which reports it.
    assert draw_shard(ex, "   ", SECRET, 2) == 0


def test_a_worker_runs_its_garbage_collector_less_often():
    # A worker keeps its solved draws for the session and solving makes no reference cycles: at Python's default
    # thresholds the collector walked that cache again and again, freeing nothing.
    import gc

    from graphkin.exercises import batch

    pool = batch._workers(1)[0]
    assert pool.submit(gc.get_threshold).result()[0] == batch._GC_THRESHOLD[0] > gc.get_threshold()[0]
    # What a chunk leaves alive (the caches) is frozen out of later collections, in a worker only.
    frozen = gc.get_freeze_count()
    pool.submit(batch._chunk, (exercises.load(NAME), "make", [("s0001", None)], SECRET, None, None)).result()
    assert pool.submit(gc.get_freeze_count).result() > 0
    batch._chunk((exercises.load(NAME), "make", [("s0001", None)], SECRET, None, None))
    assert gc.get_freeze_count() == frozen


def test_each_students_worker_is_found_once_for_a_sessions_passes(monkeypatch):
    from graphkin.exercises import batch

    found = []
    monkeypatch.setattr(batch, "draw_shard", lambda *args: found.append(args[1]) or draw_shard(*args))
    monkeypatch.setattr(batch, "_SHARDS", type(batch._SHARDS)())
    ex = exercises.load(NAME)
    keys = run_roster(ex, "key", STUDENTS, SECRET, workers=2)
    answers = [{q["id"]: q["answer"]["text"] for q in k["questions"]} for k in keys]
    run_roster(ex, "grade", STUDENTS, SECRET, answers=answers, workers=2)  # the class's values, then the grades
    assert sorted(found) == sorted(STUDENTS)
    assert batch._shards(ex, STUDENTS, SECRET, 2) == {s: draw_shard(ex, s, SECRET, 2) for s in STUDENTS}
    # Another secret is another split.
    run_roster(ex, "make", STUDENTS, SECRET + "+", workers=2)
    assert len(found) == 2 * len(STUDENTS)


def test_the_feeding_process_pauses_its_collector_only_while_it_reads_the_workers_rows():
    import gc

    ex = exercises.load(NAME)
    seen = []
    assert gc.isenabled()
    run_roster(ex, "make", STUDENTS, SECRET, workers=2, progress=lambda n: seen.append(gc.isenabled()))
    assert seen and not any(seen) and gc.isenabled()
    gc.disable()
    try:
        run_roster(ex, "make", STUDENTS, SECRET, workers=2)
        assert not gc.isenabled()  # a caller's own choice is left as it was
    finally:
        gc.enable()
    run_roster(ex, "make", STUDENTS[:PARALLEL_FROM - 1], SECRET, progress=lambda n: seen.append(gc.isenabled()))
    assert seen[-1]  # a small roster runs here, with the collector as it is
