"""The bodies' materials: no constant has a default, a published material is
named from the table fem/materials/materials.json, one yield strength per body.
Checks:
- a scenario that leaves out constants of its material model is refused (exit
  2, nothing written), naming each one with its full path and how to give it;
  an elastic-plastic body without a yield strength likewise;
- 'Material = AISI 304' on an elastic sphere: the run uses the table's constants
  (summary.json "materials", the history.h5 attributes, the start of the log) with
  origin "table" and the table's source, and the yield check uses its yield
  strength; an entry set in the scenario (Poisson's ratio) overrides the table;
- an unknown material name is refused, listing every name of the table;
- the former second yield strength, <Body>/Elastic-plastic/Yield strength, is
  refused naming the entry that replaced it; a rigid plate refuses a Material.
The run is the coarse elastic impact of bad_input.py (200 um contact elements)."""
import json
import os
import shutil
import subprocess
import h5py
from fem_test_lib import *

binary, work, _ = parse_common_arguments()
checks = Checks()
here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(here, "..", "..", "fem", "materials", "materials.json")) as f:
    TABLE = json.load(f)["materials"]
SMALL = {"Mesh/Contact element size": 200e-6}


def impact_fem(directory, arguments):
    shutil.rmtree(directory, ignore_errors=True)
    result = subprocess.run([binary] + arguments + ["--set", "Output/Directory=" + directory],
                            capture_output=True, text=True, timeout=600)
    return result.returncode, result.stdout + result.stderr


def refused(name, arguments, words):
    directory = f"{work}/materials_{name}"
    code, output = impact_fem(directory, arguments)
    print(f"[{name}] exit {code}: " + " ".join(output.strip().splitlines()[-3:])[:400])
    checks.check(code == 2, f"{name}: exit status 2 (got {code})")
    missing = [w for w in words if w not in output]
    checks.check(not missing, f"{name}: the message says {words} (missing: {missing})")
    left = [n for n in ("history.h5", "history.incomplete.h5", "summary.json")
            if os.path.exists(os.path.join(directory, n))]
    checks.check(not left, f"{name}: nothing written ({', '.join(left) or 'none'})")
    return output


# ---- constants left out: refused, named ----
refused("none_given", sets(SMALL),
        ["Sphere/Elastic/Young's modulus", "Sphere/Elastic/Poisson's ratio",
         "Sphere/Elastic/Density", "not given", "set Material = <name>", "AISI 304"])
refused("plate_density", [STEEL_PRM] + sets(dict(SMALL, **{"Plate/Elastic/Density": ""})),
        ["Plate/Elastic/Density is not given", "subsection Plate"])
refused("kelvin_voigt_retardation",
        [STEEL_PRM] + sets(dict(SMALL, **{"Sphere/Material model": "kelvin-voigt",
                                          "Sphere/Kelvin-voigt/Retardation time": ""})),
        ["Sphere/Kelvin-voigt/Retardation time is not given"])
refused("plastic_yield", [STEEL_PRM] + sets(dict(SMALL, **{"Sphere/Material model": "elastic-plastic"})),
        ["Sphere/Yield strength is not given", "elastic-plastic"])
refused("plastic_yield_zero",
        [STEEL_PRM] + sets(dict(SMALL, **{"Sphere/Material model": "elastic-plastic",
                                          "Sphere/Yield strength": 0})),
        ["Sphere/Yield strength must be > 0 Pa", "got 0"])

# ---- unknown material: refused, the known ones listed ----
refused("unknown", [STEEL_PRM] + sets(dict(SMALL, **{"Sphere/Material": "AISI 9999"})),
        ["Sphere/Material = AISI 9999 is not in the material table"] + sorted(TABLE))

# ---- the former second yield strength: refused, its replacement named ----
refused("replaced_yield",
        [STEEL_PRM] + sets(dict(SMALL, **{"Sphere/Material model": "elastic-plastic",
                                          "Sphere/Elastic-plastic/Yield strength": "2e9"})),
        ["Sphere/Elastic-plastic/Yield strength was replaced by Sphere/Yield strength",
         "set Yield strength = 2e9"])
refused("rigid_material", [STEEL_PRM] + sets(dict(SMALL, **{"Plate/Material model": "rigid",
                                                            "Plate/Material": "AISI 304"})),
        ["Plate/Material = AISI 304 has no meaning with Plate/Material model = rigid"])

# ---- Material = AISI 304: the table's constants, an explicit entry wins ----
prm = os.path.join(work, "materials_table.prm")
with open(prm, "w") as f:
    f.write("""subsection Sphere
  set Material model = elastic
  set Material       = AISI 304
  subsection Elastic
    set Poisson's ratio = 0.3
  end
end
subsection Plate
  subsection Elastic
    set Young's modulus = 2e11
    set Poisson's ratio = 0.25
    set Density         = 7800
  end
end
""")
directory = f"{work}/materials_table"
code, output = impact_fem(directory, [prm] + sets(SMALL))
print(output.strip().splitlines()[:12])
checks.check(code == 0, f"Material = AISI 304: the run ends (exit {code})")
table = TABLE["AISI 304"]["constants"]
expected = {"Young's modulus": ("Sphere/Elastic/Young's modulus", table["Young's modulus"]["value"], "table"),
            "Density": ("Sphere/Elastic/Density", table["Density"]["value"], "table"),
            "Yield strength": ("Sphere/Yield strength", table["Yield strength"]["value"], "table"),
            "Poisson's ratio": ("Sphere/Elastic/Poisson's ratio", 0.3, "scenario")}
if code == 0:
    s = summary(directory)
    sphere = s.get("materials", {}).get("sphere", {})
    print("summary.json materials.sphere:", json.dumps(sphere, indent=1)[:1500])
    checks.check(sphere.get("material") == "AISI 304" and sphere.get("material model") == "elastic",
                 "summary.json: the sphere's material AISI 304, model elastic")
    constants = sphere.get("constants", {})
    for entry, (parameter, value, origin) in expected.items():
        c = constants.get(entry, {})
        checks.check(c.get("parameter") == parameter and c.get("value") == value
                     and c.get("origin") == origin,
                     f"summary.json: {parameter} = {value:g} from the {origin} (got {c})")
        if origin == "table":
            checks.check(c.get("source") == table[entry]["source"],
                         f"summary.json: {entry} cites the table's source")
    table_poisson = table["Poisson's ratio"]["value"]
    checks.check(constants.get("Poisson's ratio", {}).get("value") != table_poisson,
                 f"the scenario's Poisson's ratio overrides the table's ({table_poisson})")
    plate = s.get("materials", {}).get("plate", {})
    checks.check(plate.get("material") is None and all(c.get("origin") == "scenario"
                                                       for c in plate.get("constants", {}).values())
                 and len(plate.get("constants", {})) == 3,
                 "summary.json: the plate's three constants from the scenario, no material")
    checks.check(s.get("yield_strength_sphere") == table["Yield strength"]["value"],
                 f"the yield check uses the table's yield strength "
                 f"({s.get('yield_strength_sphere')} Pa)")
    with h5py.File(os.path.join(directory, "history.h5"), "r") as f:
        attributes = {k: (v.decode() if isinstance(v, bytes) else v) for k, v in f.attrs.items()}
    for entry, (parameter, value, _) in expected.items():
        checks.check(float(attributes.get(parameter, "nan")) == value,
                     f"history.h5: {parameter} = {attributes.get(parameter)} (used: {value:g})")
    checks.check("Sphere/Elastic/Young's modulus = 1.93e+11 Pa  (table: AISI 304)" in output
                 and "Sphere/Elastic/Poisson's ratio = 0.3  (scenario entry)" in output,
                 "the start of the run prints each constant with its origin")
checks.finish()
