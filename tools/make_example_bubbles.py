#!/usr/bin/python3
"""Writes the default example bubble-track files (format `fluidsound.bubbles/1`, DESIGN.md).

STAND-IN EXAMPLE: until the scene pipeline (simulate -> transfer) exists, this script invents the
bubbles of a pour instead of simulating them, so that `fluidsound synth` has a realistic input.

scenes/pour.bubbles.json models a 3-second pour of water into a glass, heard by two listeners
("left", "right") in air about 1 m away:

- Births: an inhomogeneous Poisson process on 0.1-3.0 s (thinning, Lewis & Shedler 1979), rate
  rising smoothly from 0 to PEAK_RATE over the first RAMP seconds (the stream hits the water and
  the plunging jet develops), then steady. About 400 bubbles.
- Radii: Deane & Stokes (2002) piecewise power law, physics.md section 7.2: N(a) ~ a^-3/2 below
  the Hinze scale a_H = 1 mm, ~ a^-10/3 above, continuous at a_H, on 0.25-4 mm; sampled by
  inverting its cumulative distribution (83 % of bubbles below a_H on this range).
- Tracks: from birth, one sample per video frame (30 fps). A bubble is born 5-40 mm below the
  surface and rises at a constant 0.2-0.3 m/s (terminal rise speed of millimetre bubbles in
  water) until its depth reaches 1.5 R; that sample ends the track, and the synthesiser keeps
  its values while the bubble rings out (DESIGN.md).
- Transfer per listener: 2.4128e-3 (physics.md section 6 item 5: listener in air 1 m above a
  flat surface, on axis, -52.35 dB) times a stereo pan factor between 0.6 and 1.0 from the
  bubble's horizontal position x across the glass (x = -r: 1.0 left / 0.6 right). Constant along
  a track: the bubble rises straight up and the far-field transfer does not depend on depth.

scenes/single-bubble.bubbles.json: one 1 mm bubble deep in open water (no track, transfer 1, one
channel, duration by default until it has decayed by 90 dB): the simplest input there is.

Deterministic: random.Random(1); numbers rounded to 6 significant digits. Standard library only.
Usage: /usr/bin/python3 tools/make_example_bubbles.py [--out DIR]   (default DIR: <repo>/scenes)
       /usr/bin/python3 tools/make_example_bubbles.py --pour-file F --pour-end 60 --peak-rate 2000
         (a longer, denser pour only, e.g. for tools/bench.sh's 60-second memory measurement)
"""

import argparse
import json
import math
import os
import random
import tempfile

SEED = 1
SAMPLE_RATE = 48000.0  # Hz
DURATION = 3.5  # s: last birth at 3.0 s, plus time for the largest bubbles to ring out
LISTENERS = ["left", "right"]
FRAME_RATE = 30.0  # frames per second of the tracks

BIRTH_START, BIRTH_END = 0.1, 3.0  # s: the pour
RAMP = 0.5  # s: the bubble rate rises over this time after BIRTH_START
PEAK_RATE = 150.0  # bubbles per second once the pour is steady (~400 bubbles in all)

RADIUS_MIN, RADIUS_MAX = 0.25e-3, 4.0e-3  # m
HINZE_RADIUS = 1.0e-3  # m, a_H (physics.md section 7.2 default)
SLOPE_BELOW, SLOPE_ABOVE = 1.5, 10.0 / 3.0  # N(a) ~ a^-slope

BIRTH_DEPTH_MIN, BIRTH_DEPTH_MAX = 5.0e-3, 40.0e-3  # m
RISE_SPEED_MIN, RISE_SPEED_MAX = 0.2, 0.3  # m/s
END_DEPTH_IN_RADII = 1.5  # the track ends when the depth reaches 1.5 R

TRANSFER_ON_AXIS_1M = 2.4128e-3  # listener pressure / free-field pressure at 1 m (physics.md s. 6)
GLASS_RADIUS = 0.035  # m, inner radius of the glass: range of the bubbles' x
PAN_NEAR, PAN_FAR = 1.0, 0.6  # gain factor for the listener on the bubble's side / the other side

SIGNIFICANT_DIGITS = 6


def rounded(x):
    """x rounded to SIGNIFICANT_DIGITS significant digits (shortest repr in the JSON)."""
    return float(f"{x:.{SIGNIFICANT_DIGITS}g}")


def birth_rate(t):
    """Poisson rate of bubble births [1/s] at time t [s]: a raised-cosine rise, then steady."""
    if t < BIRTH_START or t > BIRTH_END:
        return 0.0
    s = min((t - BIRTH_START) / RAMP, 1.0)
    return PEAK_RATE * 0.5 * (1.0 - math.cos(math.pi * s))


def birth_times(rng):
    """Births [s] of an inhomogeneous Poisson process with rate birth_rate, by thinning: candidates
    at the constant rate PEAK_RATE, each kept with probability birth_rate(t) / PEAK_RATE."""
    times, t = [], BIRTH_START
    while True:
        t += rng.expovariate(PEAK_RATE)
        if t > BIRTH_END:
            return times
        if rng.random() * PEAK_RATE < birth_rate(t):
            times.append(t)


def deane_stokes_radius(u):
    """Radius [m] at cumulative probability u in [0, 1) of the piecewise power law on
    [RADIUS_MIN, RADIUS_MAX]: density (a/a_H)^-3/2 below a_H, (a/a_H)^-10/3 above (continuous)."""
    x_min, x_max = RADIUS_MIN / HINZE_RADIUS, RADIUS_MAX / HINZE_RADIUS  # in units of a_H
    # Integrals of x^-p over each segment, in units of a_H: (x0^(1-p) - x1^(1-p)) / (p - 1).
    below = (x_min ** (1.0 - SLOPE_BELOW) - 1.0) / (SLOPE_BELOW - 1.0)
    above = (1.0 - x_max ** (1.0 - SLOPE_ABOVE)) / (SLOPE_ABOVE - 1.0)
    target = u * (below + above)
    if target < below:  # solve (x_min^(1-p) - x^(1-p)) / (p - 1) = target for x
        base = x_min ** (1.0 - SLOPE_BELOW) - target * (SLOPE_BELOW - 1.0)
        x = base ** (1.0 / (1.0 - SLOPE_BELOW))
    else:  # solve (1 - x^(1-p)) / (p - 1) = target - below
        x = (1.0 - (target - below) * (SLOPE_ABOVE - 1.0)) ** (1.0 / (1.0 - SLOPE_ABOVE))
    return min(max(x, x_min), x_max) * HINZE_RADIUS


def pour_bubble(rng, birth):
    """One bubble of the pour: radius, birth and its rising track."""
    radius = deane_stokes_radius(rng.random())
    end_depth = END_DEPTH_IN_RADII * radius
    depth0 = rng.uniform(max(BIRTH_DEPTH_MIN, end_depth), BIRTH_DEPTH_MAX)
    speed = rng.uniform(RISE_SPEED_MIN, RISE_SPEED_MAX)
    x = rng.uniform(-GLASS_RADIUS, GLASS_RADIUS)  # across the glass, left (-) to right (+)
    side = (x / GLASS_RADIUS + 1.0) / 2.0  # 0 = far left, 1 = far right
    transfer = [rounded(TRANSFER_ON_AXIS_1M * (PAN_NEAR + (PAN_FAR - PAN_NEAR) * side)),
                rounded(TRANSFER_ON_AXIS_1M * (PAN_FAR + (PAN_NEAR - PAN_FAR) * side))]
    track, frame = [], 0
    while True:
        t = birth + frame / FRAME_RATE
        depth = max(depth0 - speed * (t - birth), end_depth)
        track.append({"t": rounded(t), "depth": rounded(depth), "transfer": transfer})
        if depth <= end_depth:
            break
        frame += 1
    return {"radius": rounded(radius), "birth": rounded(birth), "track": track}


def document_text(header, bubbles):
    """The JSON text: header fields on their own lines, then one bubble per line (compact, yet
    readable and diff-friendly)."""
    compact = {"separators": (",", ":")}
    lines = ["{"]
    lines += [f'  {json.dumps(key)}: {json.dumps(value)},' for key, value in header.items()]
    lines.append('  "bubbles": [')
    lines += ["    " + json.dumps(b, **compact) + ("," if i + 1 < len(bubbles) else "")
              for i, b in enumerate(bubbles)]
    lines += ["  ]", "}"]
    return "\n".join(lines) + "\n"


def write_atomically(path, text):
    """Writes text to a temporary file beside path, then renames it onto path."""
    folder = os.path.dirname(os.path.abspath(path))
    fd, temporary = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".tmp-", dir=folder)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            out.write(text)
        os.chmod(temporary, 0o644)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


def main():
    global BIRTH_END, PEAK_RATE  # the process model's two knobs, set once from the command line
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description="Write the example fluidsound.bubbles/1 files.")
    parser.add_argument("--out", default=os.path.join(repo, "scenes"), help="output folder")
    parser.add_argument("--pour-file", help="write only the pour, to this file")
    parser.add_argument("--pour-end", type=float, default=BIRTH_END, help="last birth [s]")
    parser.add_argument("--peak-rate", type=float, default=PEAK_RATE, help="steady births per second")
    args = parser.parse_args()
    BIRTH_END, PEAK_RATE = args.pour_end, args.peak_rate

    rng = random.Random(SEED)
    bubbles = [pour_bubble(rng, birth) for birth in birth_times(rng)]
    pour = args.pour_file or os.path.join(args.out, "pour.bubbles.json")
    write_atomically(pour, document_text(
        {"format": "fluidsound.bubbles/1", "sample_rate": int(SAMPLE_RATE),
         "duration": BIRTH_END + DURATION - 3.0, "listeners": LISTENERS}, bubbles))

    single = os.path.join(args.out, "single-bubble.bubbles.json")
    if not args.pour_file:
        write_atomically(single, document_text(
            {"format": "fluidsound.bubbles/1", "sample_rate": int(SAMPLE_RATE)},
            [{"radius": 0.001, "birth": 0.05}]))

    radii = [b["radius"] for b in bubbles]
    samples = sum(len(b["track"]) for b in bubbles)
    below = sum(r < HINZE_RADIUS for r in radii)
    print(f"{pour}: {len(bubbles)} bubbles, births {bubbles[0]['birth']:.3f}-"
          f"{bubbles[-1]['birth']:.3f} s, radii {min(radii) * 1e3:.3f}-{max(radii) * 1e3:.3f} mm "
          f"({100.0 * below / len(radii):.1f} % below a_H), {samples} track samples, "
          f"{os.path.getsize(pour) / 1024:.1f} KB")
    if not args.pour_file:
        print(f"{single}: 1 bubble, {os.path.getsize(single)} bytes")


if __name__ == "__main__":
    main()
