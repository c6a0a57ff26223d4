#!/usr/bin/env python3
"""Gold numbers from an independent implementation of CIGRE TB 601 and IEEE Std 738: statnett/linerate.

    pip install linerate==5.0.0
    python3 verification/gold/linerate_conditions.py > tests/data/linerate_conditions.csv

Regenerates `tests/data/linerate_conditions.csv`, which `tests/thermal_linerate.rs` compares with `ohl::thermal`.
linerate is run here, not copied: this script only sets up its public API (`Conductor`, `Span`, `Tower`,
`Weather`, `Cigre601`, `IEEE738`) with the conductors of `data/conductors.toml`.

Conditions (104 rows): 48 of forced or mixed convection for each standard (96 rows), every combination of
  conductor   ACSR Drake, ACSR Linnet (data/conductors.toml; emissivity as there, no sun)
  wind        0.3, 0.61, 1.0, 2.0 m/s, at 10, 45 and 90 deg to the conductor's axis
  air         10 C at 1000 m above sea level, 40 C at sea level
and 8 TB 601 rows of natural convection only
(no wind) with the span inclined by 0, 30, 60 and 75 deg (Drake, Linnet). For every row: the steady
ampacity at 100 C, the steady temperature at a current (Drake 900 A, Linnet 500 A), and the convective
cooling at 100 C.

Settings that make linerate compute the standards as `ohl` does: no sun (solar absorptivity 0), no
magnetic-core term (constant magnetic effect 1), no cap on the Reynolds number (linerate caps it at 4000 by
default for TB 601), the wind at the angle asked from the span's own azimuth, the inclination from the
towers' heights over the span's own length (both read back from linerate's Span), solver tolerance 1e-10.
"""
import math
import sys
import tomllib
from pathlib import Path

import numpy as np
import linerate

ROOT = Path(__file__).resolve().parents[2]
CATALOG = tomllib.loads((ROOT / "data" / "conductors.toml").read_text())["conductor"]
CURRENT = {"ACSR Drake": 900.0, "ACSR Linnet": 500.0}
TIME = np.datetime64("2016-06-10 00:00")


def conductor(name):
    c = next(c for c in CATALOG if c["name"] == name)
    return linerate.Conductor(
        core_diameter=c["core_diameter_m"],
        conductor_diameter=c["diameter_m"],
        outer_layer_strand_diameter=c["outer_strand_diameter_m"],
        emissivity=c["emissivity"],
        solar_absorptivity=0.0,
        temperature1=c["temperature_low_k"] - 273.15,
        temperature2=c["temperature_high_k"] - 273.15,
        resistance_at_temperature1=c["resistance_low_ohm_per_m"],
        resistance_at_temperature2=c["resistance_high_ohm_per_m"],
        aluminium_cross_section_area=c["aluminium_area_m2"],
        constant_magnetic_effect=1.0,
        current_density_proportional_magnetic_effect=0.0,
        max_magnetic_core_relative_resistance_increase=1.0,
    )


def span(name, altitude_m, inclination_deg):
    """An east-west span about 14 m long at latitude 50 N; the far tower raised for the inclination."""
    start = linerate.Tower(longitude=0.0, latitude=50.0, altitude=altitude_m)
    flat = linerate.Span(conductor(name), start, linerate.Tower(longitude=0.0002, latitude=50.0, altitude=altitude_m), 1)
    rise = flat.span_length * math.tan(math.radians(inclination_deg))
    end = linerate.Tower(longitude=0.0002, latitude=50.0, altitude=altitude_m + rise)
    return linerate.Span(conductor(name), start, end, 1)


def row(standard, name, air_c, wind, angle_deg, altitude_m, inclination_deg):
    s = span(name, altitude_m, inclination_deg)
    w = linerate.Weather(
        air_temperature=air_c,
        wind_direction=s.conductor_azimuth + math.radians(angle_deg),
        wind_speed=wind,
        ground_albedo=0.1,
        clearness_ratio=1.0,
    )
    if standard == "cigre601":
        m = linerate.Cigre601(s, w, TIME, max_reynolds_number=1e12)
    else:
        m = linerate.IEEE738(s, w, TIME)
    ampacity = float(m.compute_steady_state_ampacity(100.0, 0.0, 10000.0, tolerance=1e-10))
    temperature = float(m.compute_conductor_temperature(CURRENT[name], air_c, 400.0, tolerance=1e-10))
    convection = float(m.compute_convective_cooling(100.0))
    return [standard, name, air_c, wind, angle_deg, repr(float(s.conductor_altitude)),
            repr(math.degrees(float(s.inclination))), 100.0, repr(ampacity), CURRENT[name],
            repr(temperature), repr(convection)]


def main():
    out = sys.stdout
    out.write(f"# linerate {linerate.__version__}: python3 verification/gold/linerate_conditions.py\n")
    out.write("standard,conductor,air_c,wind_m_per_s,angle_deg,elevation_m,inclination_deg,t_max_c,"
              "ampacity_a,current_a,temperature_c,convection_w_per_m_at_t_max\n")
    for standard in ["cigre601", "ieee738"]:
        for name in CURRENT:
            for air_c, altitude in [(10.0, 1000.0), (40.0, 0.0)]:
                for wind in [0.3, 0.61, 1.0, 2.0]:
                    for angle in [10.0, 45.0, 90.0]:
                        out.write(",".join(map(str, row(standard, name, air_c, wind, angle, altitude, 0.0))) + "\n")
    for name in CURRENT:
        for inclination in [0.0, 30.0, 60.0, 75.0]:
            out.write(",".join(map(str, row("cigre601", name, 40.0, 0.0, 90.0, 0.0, inclination))) + "\n")


if __name__ == "__main__":
    main()
