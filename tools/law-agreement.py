#!/usr/bin/env python3
"""How often the landing laws agree with a campaign's measurement (docs/landing.md, The drop law).

Reads summary.json files written by `footsim campaign` and counts, terrain by terrain, the cells the
measurement decides (success rate >= 0.7: lands; <= 0.3: falls; between: undecided, not counted)
and how many of them each rule gets right: the static pitch-stiffness law (law_prediction), the drop
law (drop_law_prediction), and the two constant verdicts "always lands" and "always falls". Cells
without a verdict (no robot, a robot on a slide, a biped for the drop law) are left out of that
rule's count and said. Every miss of the drop law is listed with its numbers.

With --laws FILE (the JSON of build/law-cells CAMPAIGN, the laws worked out without a trial) the
laws of each cell are taken from it, matched by foot, terrain and robot: a campaign's measurement
judged by a law newer than its summary.

usage: tools/law-agreement.py SUMMARY.json... [--foot NAME] [--laws FILE]
"""
import json
import sys

LANDS, FALLS = 0.7, 0.3


def decided(rate):
    return "lands" if rate >= LANDS else "falls" if rate <= FALLS else None


def verdict(text):
    return {"stands": "lands", "topples": "falls"}.get(text)


def main(argv):
    foot = None
    laws = None
    paths = []
    it = iter(argv)
    for a in it:
        if a == "--foot":
            foot = next(it)
        elif a == "--laws":
            with open(next(it)) as f:
                laws = {(r["foot"], r["terrain"], r["robot"]): r for r in json.load(f)["rows"]}
        else:
            paths.append(a)
    if not paths:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    for path in paths:
        with open(path) as f:
            s = json.load(f)
        print(f"## {path}: campaign {s['campaign']}, {s['seeds']} seeds a cell\n")
        groups = {}
        for r in s["rows"]:
            if laws is not None:
                r.update({k: v for k, v in laws[(r["foot"], r["terrain"], r["robot"])].items()
                          if k.startswith("law_") or k.startswith("drop_law_")})
            if foot and r["foot"] != foot:
                continue
            ground = r["terrain"].split("@")[0]
            groups.setdefault(ground, []).append(r)
        print("| terrain | cells | decided (lands / falls) | static law | drop law | always lands | always falls |")
        print("|---|--:|--:|--:|--:|--:|--:|")
        misses = []
        for ground, rows in groups.items():
            dec = [(r, decided(r["success_rate"])) for r in rows]
            dec = [(r, d) for r, d in dec if d]
            nl = sum(d == "lands" for _, d in dec)
            counts = {}
            for rule, key in (("static", "law_prediction"), ("drop", "drop_law_prediction")):
                judged = [(r, d) for r, d in dec if verdict(r.get(key))]
                right = sum(verdict(r.get(key)) == d for r, d in judged)
                counts[rule] = f"{right} of {len(judged)}"
                if rule == "drop":
                    misses += [(ground, r, d) for r, d in judged if verdict(r.get(key)) != d]
            print(f"| {ground} | {len(rows)} | {len(dec)} ({nl} / {len(dec) - nl}) | {counts['static']} | "
                  f"{counts['drop']} | {nl} | {len(dec) - nl} |")
        print()
        for ground, r, d in misses:
            where = r["terrain"]
            print(f"- drop law misses {r['foot']} on {where} under {r['robot']}: measured {r['landed']} of "
                  f"{r['trials']} ({d}); drop law {r.get('drop_law_prediction')} (stands in {r.get('drop_law_stands')} of "
                  f"{r.get('drop_law_seeds')} seeds), E {r.get('drop_law_energy_J')}, B {r.get('drop_law_barrier_J')}, "
                  f"M_s {r.get('drop_law_saturation_N_m')}; static law {r.get('law_prediction')}")
        print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
