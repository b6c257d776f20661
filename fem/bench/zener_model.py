"""Zener's thin-plate model through `impact-reduced thin-plate`, for the thin-plate benchmark
scripts (thin_plate.sh, thin_plate_threshold.py): the study's steel sphere on a steel plate of
fem/scenarios/thin_plate.prm, Hertz contact with optional Hunt-Crossley damping b.
"""
import json
import subprocess

E, NU, RHO, R = 2e11, 0.25, 7800, 0.01452  # Pa, -, kg/m^3, m: fem/scenarios/thin_plate.prm


def impact(reduced, h, v, b=0.0):
    """The first impact (dict of impact-reduced's JSON) of the sphere at v [m/s] on the plate of
    thickness h [m], with contact damping b [s/m]; reduced is the impact-reduced executable."""
    out = subprocess.run([reduced, "thin-plate", "--plate-modulus", str(E), "--plate-poisson", str(NU),
                          "--plate-density", str(RHO), "--thickness", str(h), "--sphere-modulus", str(E),
                          "--sphere-poisson", str(NU), "--radius", str(R), "--sphere-density", str(RHO),
                          "--damping", str(b), "--velocity", str(v)],
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out)["impacts"][0]
