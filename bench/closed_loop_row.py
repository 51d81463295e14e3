#!/usr/bin/python3
"""One row of bench/closed_loop.sh's CSV, from a set's two diagnoses and the first one's plan:

    bench/closed_loop_row.py HIDDEN SEED BEFORE.json PLAN.json AFTER.json WALL_BEFORE_S WALL_AFTER_S

PLAN.json and AFTER.json may be "-" (no test was proposed: the first diagnosis left only the
baseline standing); WALL_AFTER_S is then empty. Besides the answers, the row says how the hidden
mechanism itself stood in each diagnosis (its held-out gain and its profile likelihood ratio),
so that a test that moved it towards being named shows even where the answer did not change.
"""
import json
import sys

HEADER = ("hidden,seed,cause_before,cause_after,footprint_before,footprint_after,proposed,separation,"
          "closest_pair,candidates,hidden_gain_before,hidden_gain_after,hidden_ratio_before,"
          "hidden_ratio_after,wall_before_s,wall_after_s")


def standing(diagnosis, mechanism):
    """The hidden mechanism's held-out gain and profile likelihood ratio, or empty fields."""
    for entry in diagnosis["ranking"] if diagnosis else []:
        if entry["mechanism"] == mechanism:
            ratio = (entry.get("profile") or {}).get("likelihood_ratio")
            return "%.3g" % entry["heldout_gain"], "" if ratio is None else "%.3g" % ratio
    return "", ""


def quoted(text):
    return '"%s"' % text.replace('"', "'")


def main():
    if len(sys.argv) == 2 and sys.argv[1] == "--header":
        print(HEADER)
        return
    if len(sys.argv) != 8:
        sys.exit(__doc__.strip().splitlines()[2].strip())
    hidden, seed, before_file, plan_file, after_file, wall_before, wall_after = sys.argv[1:]
    before = json.load(open(before_file))
    plan = json.load(open(plan_file)) if plan_file != "-" else {"tests": [], "candidates": []}
    after = json.load(open(after_file)) if after_file != "-" else None
    best = plan["tests"][0] if plan["tests"] and after else None
    gain_before, ratio_before = standing(before, hidden)
    gain_after, ratio_after = standing(after, hidden)
    fields = [hidden, seed, before["cause"], (after or before)["cause"], before.get("footprint") or "",
              (after or before).get("footprint") or "", quoted(best["description"]) if best else "",
              "%.3g" % best["separation"] if best else "", best["closest_pair"] if best else "",
              " ".join(c["name"] for c in plan["candidates"]), gain_before, gain_after, ratio_before,
              ratio_after, wall_before, wall_after if after else ""]
    print(",".join(fields))


if __name__ == "__main__":
    main()
