"""compare() of two pipeline summaries (see pipeline_summary.py); no ParaView needed."""


def compare(reference, other, gamma_tolerance=1e-9):
    """Differences between two summaries, as readable lines (empty: the same). An empty dataset (GL
    Collision Verifier when nothing collides) reaches a client-server client or the root of an MPI run
    without its empty point and cell arrays (ParaView's data delivery drops them), so only its field
    data, the verdict, is compared."""
    problems = []
    if sorted(reference) != sorted(other):
        problems.append("outputs %s vs %s" % (sorted(reference), sorted(other)))
    for key in sorted(set(reference) & set(other)):
        a, b = reference[key], other[key]
        for field in ("class", "points", "cells"):
            if a[field] != b[field]:
                problems.append("%s: %s %s vs %s" % (key, field, a[field], b[field]))
        arrays_a, arrays_b = a["arrays"], b["arrays"]
        if a["points"] == 0 and a["cells"] == 0:
            arrays_a = {k: v for k, v in arrays_a.items() if k.startswith("field/")}
            arrays_b = {k: v for k, v in arrays_b.items() if k.startswith("field/")}
        if arrays_a != arrays_b:
            only_a = sorted(set(arrays_a) - set(arrays_b))
            only_b = sorted(set(arrays_b) - set(arrays_a))
            differ = sorted(k for k in set(arrays_a) & set(arrays_b) if arrays_a[k] != arrays_b[k])
            problems.append("%s: arrays only in the reference %s, only in the other %s, other counts %s"
                            % (key, only_a, only_b, {k: (arrays_a[k], arrays_b[k]) for k in differ}))
        if "gamma" in a:
            if "gamma" not in b or any(abs(x - y) > gamma_tolerance * max(1.0, abs(x))
                                       for x, y in zip(a["gamma"], b["gamma"])):
                problems.append("%s: Gamma range %s vs %s" % (key, a["gamma"], b.get("gamma")))
    return problems
