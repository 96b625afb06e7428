"""Writes a smooth 6-joint trajectory as `dynamics size --csv` reads it (t,q1..q6; the command
estimates q̇ and q̈): `python3 bench/size/trajectory.py SAMPLES > FILE`. Each joint swings as
q_i = a_i sin(2π f_i t) over 10 s, sampled evenly. Used by bench/size/run; not committed data."""
import math
import sys

samples = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
amplitude = [1.2, 0.8, 1.0, 1.5, 1.0, 2.0]
frequency = [0.2, 0.3, 0.25, 0.5, 0.4, 0.6]
out = sys.stdout
out.write("t," + ",".join(f"q{i + 1}" for i in range(6)) + "\n")
for k in range(samples):
    t = 10.0 * k / (samples - 1)
    q = (a * math.sin(2 * math.pi * f * t) for a, f in zip(amplitude, frequency))
    out.write(f"{t!r}," + ",".join(repr(x) for x in q) + "\n")
