"""A student's sheet (or key) and a graded answer sheet, as text: what ``graphkin exercise`` prints."""

from __future__ import annotations

from graphkin.notation import citation, unit_text


def format_sheet(sheet: dict) -> str:
    """A student's sheet (or key) as text."""
    lines = [sheet["title"], f"student: {sheet['student']}"]
    if sheet.get("source"):
        lines.append(f"source: {citation(sheet['source'])}")  # one line: the catalog's provenance is the teacher's
    if sheet.get("intro"):
        lines += ["", sheet["intro"].strip()]
    lines += ["", "Your data"]
    lines += [f"  {g['shown']}" + (f"   ({g['label']})" if g["label"] else "") for g in sheet["data"]]
    lines += ["", "Questions"]
    for q in sheet["questions"]:
        unit = unit_text(q["unit"]) or "no unit"
        lines.append(f"  {q['id']}: {q['ask']}   [{unit}, within {q['within']}, {q['points']:g} point"
                     f"{'s' if q['points'] != 1 else ''}]")
        if "answer" in q:
            lines.append(f"      answer: {q['answer']['text']}")
    return "\n".join(lines)


def format_report(report: dict) -> str:
    """A graded answer sheet as text."""
    lines = [f"{report['exercise']}, student {report['student']}: {report['score']:g} / {report['max']:g}"]
    for q in report["questions"]:
        slip = f" ({q['slip']})" if q["slip"] else ""
        lines.append(f"  {q['id']:<10} {q['verdict']}{slip:<20} {q['score']:g}/{q['max']:g}   {q['answer']}")
        lines.append(f"      {q['feedback']}")
        if "expected" in q:
            lines.append(f"      expected: {q['expected']}")
    if report.get("ignored"):
        lines.append(f"  not questions of this exercise (ignored): {', '.join(report['ignored'])}")
    return "\n".join(lines)
