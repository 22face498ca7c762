#!/usr/bin/env python3
"""Check the lubricated mode of `runin piston-ring` (inputs/piston_ring_lubricated.toml, doc/lubricated_piston_ring.md).

usage: check_lubricated_ring.py OUTPUT_DIR LAW_JSON [--png]

Asserts the regime (dead centres mixed: first-cycle min lambda < 3; mid-stroke full film: lambda > 5 somewhere in
the cycle), the run-in (cycle-mean mu, asperity share and R non-increasing; final share < 1 % of the first; the
worn depth still inside the law's depth table), the wear bookkeeping (worn volume = sum of jump x cycle volume),
the Stribeck curve (asperity share from ~1 to ~0 as the speed rises) and the VTK series.
"""
import csv
import json
import os
import sys


def rows(path):
    with open(path, newline="") as f:
        return [{k: (v if k == "which" else float(v)) for k, v in r.items()} for r in csv.DictReader(f)]


def main():
    out, law_path = sys.argv[1], sys.argv[2]
    law = json.load(open(law_path))
    run = rows(os.path.join(out, "lubricated.csv"))
    cyc = rows(os.path.join(out, "lubricated_cycle.csv"))
    strib = rows(os.path.join(out, "stribeck.csv"))
    errors = []

    def check(ok, what):
        if not ok:
            errors.append(what)

    first, last = run[0], run[-1]
    check(first["min_lambda"] < 3.0, f"dead centres not mixed: first-cycle min lambda {first['min_lambda']}")
    lam_first = [r["lambda"] for r in cyc if r["which"] == "first"]
    check(max(lam_first) > 5.0, f"no full film at mid-stroke: max lambda {max(lam_first)}")
    for a, b in zip(run, run[1:]):
        check(b["mu"] <= a["mu"] * (1 + 1e-3), f"mu rises by more than the law's scatter (1e-3) at cycle {b['cycle']}: {a['mu']} -> {b['mu']}")
        check(b["asperity_share"] <= a["asperity_share"], f"asperity share rises at cycle {b['cycle']}")
        check(b["R_m"] <= a["R_m"], f"R rises at cycle {b['cycle']}")
    check(last["asperity_share"] < 0.01 * first["asperity_share"],
          f"the film did not take over: share {first['asperity_share']} -> {last['asperity_share']}")
    depth_end = law["worn_depth"][-1]
    final_max = last["max_worn_depth_m"]   # at the start of the last computed cycle
    check(final_max < depth_end, f"max worn depth {final_max} beyond the law's table ({depth_end})")
    booked = sum(r["cycles_jumped"] * r["cycle_wear_volume_m3"] for r in run[:-1])
    check(abs(booked - last["worn_volume_m3"]) <= 1e-9 * last["worn_volume_m3"],
          f"wear bookkeeping: {booked} vs {last['worn_volume_m3']}")
    check(strib[0]["asperity_share"] > 0.9, f"stribeck: low-speed share {strib[0]['asperity_share']}")
    check(strib[-1]["asperity_share"] < 1e-6, f"stribeck: high-speed share {strib[-1]['asperity_share']}")
    for stem in ("lubricated_first", "lubricated_last"):
        check(os.path.exists(os.path.join(out, "vtk", stem + ".pvd")), f"missing vtk/{stem}.pvd")
    if "--png" in sys.argv:
        for png in ("lubricated.png", "stribeck.png"):
            check(os.path.getsize(os.path.join(out, png)) > 1000, f"{png} missing or empty")
    if errors:
        print("\n".join(errors))
        sys.exit(1)
    print(f"ok: {len(run)} computed cycles; mu {first['mu']:.5g} -> {last['mu']:.5g}, share "
          f"{first['asperity_share']:.4g} -> {last['asperity_share']:.4g}, min lambda {first['min_lambda']:.3f} -> "
          f"{last['min_lambda']:.3f}, R {1e9 * first['R_m']:.4g} -> {1e9 * last['R_m']:.4g} nm")


if __name__ == "__main__":
    main()
