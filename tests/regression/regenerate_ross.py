"""Regenerates the ROSS reference of tests/consistency/test_ross_reference.py (needs ROSS):

    pip install 'auxbearing[ross]'; python tests/regression/regenerate_ross.py

Builds a compressor-like rotor in ROSS 2.3 (a stepped steel shaft in 16 elements, an overhung impeller, a
coupling hub, two linear bearings), saves it as ROSS does (ross_rotor.toml), and writes what the test needs
without ROSS: the free-free lateral matrices and the bearings as this project reads them from the ROSS file
(ross_rotor.npz), and ROSS's own damped natural frequencies from Rotor.run_modal at four speeds
(ross_reference.json; ROSS lists lateral, axial and torsional modes together).
"""

import json
from pathlib import Path

import numpy as np

HERE = Path(__file__).parent
SPEEDS = (0.0, 500.0, 1000.0, 1500.0)  #: rad/s


def build():
    """The ROSS rotor of the reference."""
    import ross as rs

    steel = rs.materials.steel
    lengths = [0.04, 0.04, 0.04, 0.04, 0.06, 0.08, 0.08, 0.08, 0.08, 0.08, 0.08, 0.06, 0.04, 0.04, 0.04, 0.04]
    outer = [0.04, 0.04, 0.05, 0.05, 0.07, 0.09, 0.09, 0.09, 0.09, 0.09, 0.09, 0.07, 0.05, 0.05, 0.05, 0.05]
    shaft = [rs.ShaftElement(L=L, idl=0.0, odl=d, material=steel, shear_effects=True, rotary_inertia=True,
                             gyroscopic=True) for L, d in zip(lengths, outer, strict=True)]
    disks = [rs.DiskElement(n=1, m=6.0, Id=0.025, Ip=0.045, tag="impeller"),
             rs.DiskElement(n=16, m=2.0, Id=0.004, Ip=0.006, tag="coupling hub")]
    bearings = [rs.BearingElement(n=3, kxx=2e7, kyy=2e7, cxx=2e3, cyy=2e3, tag="impeller-end bearing"),
                rs.BearingElement(n=13, kxx=2e7, kyy=2e7, cxx=2e3, cyy=2e3, tag="coupling-end bearing")]
    return rs.Rotor(shaft, disks, bearings)


if __name__ == "__main__":
    import ross

    from auxbearing.machine.ross_rotor import structure_from_ross, supports_from_ross

    rotor = build()
    rotor.save(str(HERE / "ross_rotor.toml"))
    structure = structure_from_ross(rotor, "ross_rotor.toml")
    supports = supports_from_ross(rotor, 0.0)
    rows = [[s.position, s.kxx, s.kxy, s.kyx, s.kyy, s.cxx, s.cxy, s.cyx, s.cyy] for s in supports]
    np.savez(HERE / "ross_rotor.npz", M=structure.mass, K=structure.stiffness, G=structure.gyroscopic,
             nodes=structure.nodes, supports=np.array(rows))
    reference = {"ross_version": ross.__version__, "command": "python tests/regression/regenerate_ross.py",
                 "speeds_rad_s": list(SPEEDS), "damped_natural_frequencies_rad_s": []}
    for speed in SPEEDS:
        modal = rotor.run_modal(speed=speed, num_modes=24)
        reference["damped_natural_frequencies_rad_s"].append([float(w) for w in modal.wd])
    (HERE / "ross_reference.json").write_text(json.dumps(reference, indent=1) + "\n")
    print("wrote ross_rotor.toml, ross_rotor.npz, ross_reference.json")
