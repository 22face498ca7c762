#!/usr/bin/env python3
"""Writes synthetic_law.json: a runin-state-law v1 file from closed forms (the continuum's state-law tests).

mu_body(p, h)   = 0.15 + (0.35 + 0.05 log10(p / 1e7)) exp(-h / hc)      run-in from a pressure-dependent peak
wear_rate(p, h) = (k/H) p (0.2 + 0.8 exp(-h / hc))                      Archard-like, decaying with h
counterface     = 0.3 wear_rate
sliding_distance(p, h) = int_0^h dh' / wear_rate(p, h')                 closed form
Rq, Rsk, area_fraction: smooth placeholders. Run: python3 make_synthetic_law.py > synthetic_law.json; python3 make_synthetic_law.py 1e-11 > fast_law.json
"""
import json
import math
import sys

# 1e-13 (default): synthetic_law.json; 1e-11: fast_law.json (the short runs of the line contacts)
K_OVER_H = float(sys.argv[1]) if len(sys.argv) > 1 else 1e-13  # 1/Pa
HC = 4e-7         # m
# 1e6 .. 1e9 Pa; the fast law from 1e4 Pa (the line contacts' edges)
pressure = [1e6 * 10 ** (0.5 * i) for i in range(7)] if K_OVER_H == 1e-13 else [1e4 * 10 ** (0.5 * i) for i in range(11)]
depth = [2e-6 * j / 40 for j in range(41)]


def mu(p, h):
    return 0.15 + (0.35 + 0.05 * math.log10(p / 1e7)) * math.exp(-h / HC)


def wear(p, h):
    return K_OVER_H * p * (0.2 + 0.8 * math.exp(-h / HC))


def distance(p, h):
    # d s = dh / (a (0.2 + 0.8 e^{-h/hc})), a = kp/H; with u = e^{h/hc}: s = hc/(0.2 a) ln((0.2 u + 0.8) / 1.0)
    a = K_OVER_H * p
    return HC / (0.2 * a) * math.log(0.2 * math.exp(h / HC) + 0.8)


def table(f):
    return {"mean": [[f(p, h) for h in depth] for p in pressure]}


law = {
    "format": "runin-state-law",
    "version": 1,
    "pressure": pressure,
    "worn_depth": depth,
    "fields": {
        "mu_body": table(mu),
        "rq": table(lambda p, h: 1e-7 * (0.3 + 0.7 * math.exp(-h / HC))),
        "rsk": table(lambda p, h: -0.5 * (1 - math.exp(-h / HC))),
        "area_fraction": table(lambda p, h: min(1.0, 0.05 + 0.1 * (1 - math.exp(-h / HC)))),
        "wear_rate": table(wear),
        "counterface_wear_rate": table(lambda p, h: 0.3 * wear(p, h)),
        "sliding_distance": table(distance),
    },
    "material": "synthetic",
    "provenance": {"generator": "tests/data/state_law/make_synthetic_law.py", "k_over_h": K_OVER_H},
}
print(json.dumps(law, indent=1))
