"""Thesis claims 2 and 3 on a mu0 sweep (stdlib only), shared by the check_*_csv.py scripts.

Each curve is (t, friction_force, speed) sampled on the CLI's output grid. Per curve:
  peak    max |F| over the run
  start   max |F| over the first `start_fraction` of the run (the break-away peak)
  steady  |F| at the last sample
  t_eq    time to equilibrium: the first sample time after which |F| and the speed stay within
          `tolerance` (2 %) of their final values (speed band at least 1e-3 of the peak speed);
          None if that is in the last 10 % of the run (not shown to be steady).
Claim 2: for successive mu0 (high, low) peak_high >= (1 + peak_margin) peak_low and
         t_eq_high >= (1 + time_margin) t_eq_low, every t_eq found.
Claim 3: start >= (1 + start_margin) steady for every mu0.
"""


def settle_time(t, values, band):
    final = values[-1]
    for i in range(len(t) - 1, -1, -1):
        if abs(values[i] - final) > band:
            return t[min(i + 1, len(t) - 1)]
    return t[0]


def curve_stats(t, force, speed, tolerance=0.02, start_fraction=0.05):
    span = t[-1] - t[0]
    magnitude = [abs(f) for f in force]
    peak = max(magnitude)
    start = max(m for x, m in zip(t, magnitude) if x <= t[0] + start_fraction * span)
    steady = magnitude[-1]
    speed_band = max(tolerance * abs(speed[-1]), 1e-3 * max(abs(v) for v in speed))
    t_eq = max(settle_time(t, magnitude, tolerance * steady), settle_time(t, speed, speed_band))
    if t_eq > t[0] + 0.9 * span:
        t_eq = None
    return {"peak": peak, "start": start, "steady": steady, "t_eq": t_eq}


def check_claims(curves, peak_margin, time_margin, start_margin, tolerance=0.02):
    """curves: {mu0: (t, force, speed)}. Returns a list of problems; prints the table."""
    problems = []
    stats = []
    for mu0 in sorted(curves, reverse=True):
        s = curve_stats(*curves[mu0], tolerance=tolerance)
        stats.append((mu0, s))
        t_eq = "not reached" if s["t_eq"] is None else f"{s['t_eq']:.6g} s"
        print(f"mu0 {mu0:g}: peak {s['peak']:.6g} N, start {s['start']:.6g} N, steady {s['steady']:.6g} N, "
              f"equilibrium from {t_eq}")
        if s["t_eq"] is None:
            problems.append(f"claim 2: mu0 {mu0} does not reach equilibrium (2 % band) before the last 10 % of the run")
        if not s["start"] >= (1 + start_margin) * s["steady"]:
            problems.append(f"claim 3: start friction {s['start']} not >= {1 + start_margin} x steady {s['steady']} "
                            f"at mu0 {mu0}")
    for (mu_hi, hi), (mu_lo, lo) in zip(stats, stats[1:]):
        if not hi["peak"] >= (1 + peak_margin) * lo["peak"]:
            problems.append(f"claim 2: peak {hi['peak']} at mu0 {mu_hi} not >= {1 + peak_margin} x {lo['peak']} "
                            f"at mu0 {mu_lo}")
        if hi["t_eq"] is not None and lo["t_eq"] is not None and not hi["t_eq"] >= (1 + time_margin) * lo["t_eq"]:
            problems.append(f"claim 2: time to equilibrium {hi['t_eq']} at mu0 {mu_hi} not >= {1 + time_margin} x "
                            f"{lo['t_eq']} at mu0 {mu_lo}")
    return problems
