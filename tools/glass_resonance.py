#!/usr/bin/python3
"""Measurement (not a test) of a filling glass's air-column resonance in a render (issue 20):
for each 0.25 s window of the WAV, the frequency of the strongest spectral peak between 0.3 and
4 kHz, and the air column the bubbles measure (rim height minus the mean surface height over the
window's track samples near the glass's axis, position + depth), against the quarter-wave formula
c_a / (4 (L + 0.6133 r)).

usage: tools/glass_resonance.py OUTDIR/NAME.wav OUTDIR/bubbles.json --rim Y --axis X Z --radius R
       [--channel N] [--window S]
Standard library only (Debian's /usr/bin/python3): the WAV is IEEE float, as fluidsound writes it.
"""
import argparse
import cmath
import json
import math
import struct
import sys

SOUND_SPEED_AIR = 343.2  # c_a [m/s], 20 °C (acoustics/bubble/liquid_properties.h)
END_CORRECTION = 0.6133  # unflanged open end, Levine & Schwinger 1948


def read_wav(path):
    data = open(path, "rb").read()
    if data[:4] != b"RIFF" or data[8:12] != b"WAVE":
        sys.exit(f"{path}: expected a RIFF/WAVE file")
    at, fmt, samples = 12, None, None
    while at + 8 <= len(data):
        chunk, size = data[at:at + 4], struct.unpack("<I", data[at + 4:at + 8])[0]
        if chunk == b"fmt ":
            fmt = struct.unpack("<HHIIHH", data[at + 8:at + 24])
        elif chunk == b"data":
            samples = data[at + 8:at + 8 + size]
        at += 8 + size + (size & 1)
    if fmt is None or samples is None or fmt[5] not in (32, 64):
        sys.exit(f"{path}: expected float samples (32 or 64 bit)")
    channels, rate, bits = fmt[1], fmt[2], fmt[5]
    values = struct.unpack("<%d%s" % (len(samples) * 8 // bits, "f" if bits == 32 else "d"), samples)
    return rate, [values[c::channels] for c in range(channels)]


def fft(x):
    """Radix-2 decimation in time; len(x) a power of two."""
    n = len(x)
    if n == 1:
        return list(x)
    even, odd = fft(x[0::2]), fft(x[1::2])
    out = [0j] * n
    for k in range(n // 2):
        t = cmath.exp(-2j * math.pi * k / n) * odd[k]
        out[k], out[k + n // 2] = even[k] + t, even[k] - t
    return out


def strongest_peak(signal, rate, lo, hi):
    size = 1
    while size < 2 * len(signal):
        size *= 2
    hann = [0.5 - 0.5 * math.cos(2 * math.pi * i / (len(signal) - 1)) for i in range(len(signal))]
    spectrum = fft([s * w for s, w in zip(signal, hann)] + [0.0] * (size - len(signal)))
    bins = range(int(lo * size / rate) + 1, int(hi * size / rate))
    best = max(bins, key=lambda k: abs(spectrum[k]))
    return best * rate / size


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("wav")
    parser.add_argument("bubbles")
    parser.add_argument("--rim", type=float, required=True, help="rim height y [m]")
    parser.add_argument("--axis", type=float, nargs=2, required=True, help="glass axis x z [m]")
    parser.add_argument("--radius", type=float, required=True, help="inner radius r [m]")
    parser.add_argument("--channel", type=int, default=0)
    parser.add_argument("--window", type=float, default=0.25, help="[s]")
    a = parser.parse_args()
    rate, channels = read_wav(a.wav)
    signal = channels[a.channel]
    tracks = json.load(open(a.bubbles))["bubbles"]
    rows = []
    start = 0.0
    while (start + a.window) * rate <= len(signal):
        levels = [s["position"][1] + s["depth"] for b in tracks for s in b.get("track", [])
                  if start <= s["t"] < start + a.window and "position" in s
                  and math.hypot(s["position"][0] - a.axis[0], s["position"][2] - a.axis[1]) < a.radius]
        window = signal[int(start * rate):int((start + a.window) * rate)]
        peak = strongest_peak(window, rate, 300.0, 4000.0) if any(window) else float("nan")
        if levels:
            column = a.rim - sorted(levels)[len(levels) // 2]
            expected = SOUND_SPEED_AIR / (4 * (column + END_CORRECTION * a.radius))
            rows.append((start, column, expected, peak))
        start += a.window
    print(f"{'window_s':>8} {'column_m':>8} {'quarter_wave_hz':>15} {'peak_hz':>8} {'ratio':>6}")
    for start, column, expected, peak in rows:
        print(f"{start:8.2f} {column:8.4f} {expected:15.0f} {peak:8.0f} {peak / expected:6.2f}")
    rises = sum(1 for p, q in zip(rows, rows[1:]) if q[3] >= p[3])
    within = sum(1 for r in rows if abs(r[3] / r[2] - 1) <= 0.10)
    if len(rows) > 1:
        print(f"peak rises in {rises} of {len(rows) - 1} steps ({100 * rises / (len(rows) - 1):.0f} %); "
              f"within 10 % of the quarter wave in {within} of {len(rows)} windows")


if __name__ == "__main__":
    main()
