"""Builds the shipped compressor's rotor matrices: ``python examples/compressor_rotor.py``.

With ``--ross`` (and ROSS installed: ``pip install 'auxbearing[ross]'``) it also builds the same shaft in ROSS
(Euler-Bernoulli elements with rotary inertia, the same disks) and saves it as ROSS does, into
``examples/compressor_ross/compressor_rotor.toml``, which ``examples/compressor_ross/compressor.toml`` reads
through ``[rotor] ross_file``: the compressor as a ROSS user would bring it.

Writes ``src/auxbearing/catalog/machines/compressor.npz`` (the arrays M, K, G and nodes that
``[rotor] matrices`` reads) and prints its node positions, where the machine file's stations sit (in
the matrices' own frame, from the impeller end). The rotor is illustrative, not a real machine: a 40 kg
steel shaft 0.88 m long with an overhung impeller, two magnetic-bearing sleeves, a motor section and
50 mm journals at the touchdown planes; its first free-free bending mode is at about 390 Hz, near the
250 Hz of its 15 000 rpm.
"""

from pathlib import Path

import numpy as np

from auxbearing.machine.structure import beam_structure, modal_rotor

#: Node positions from the impeller end [m] and each element's diameter [m].
NODES = np.array([0, 0.04, 0.08, 0.12, 0.16, 0.22, 0.30, 0.38, 0.46, 0.54, 0.62, 0.70, 0.76, 0.80, 0.84, 0.88])
DIAMETERS = np.array([40, 40, 50, 50, 70, 70, 90, 90, 90, 90, 70, 70, 50, 50, 50]) * 1e-3
#: Rigid disks (node, mass [kg], J_t, J_p [kg m^2]): the impeller, the two magnetic-bearing sleeves.
DISKS = [(1, 6.0, 0.025, 0.045), (5, 3.0, 0.006, 0.008), (11, 3.0, 0.006, 0.008)]
STEEL = {"density": 7850.0, "youngs_modulus": 2.1e11}
TARGET = Path(__file__).resolve().parents[1] / "src" / "auxbearing" / "catalog" / "machines" / "compressor.npz"


def compressor_structure():
    """The compressor rotor, its nodes measured from the impeller end."""
    return beam_structure(NODES, DIAMETERS, STEEL["density"], STEEL["youngs_modulus"], disks=DISKS)


def compressor_ross():
    """The same rotor as a ``ross.Rotor`` (no bearings: the machine file gives its stations)."""
    import ross as rs

    steel = rs.Material(name="compressor_steel", rho=STEEL["density"], E=STEEL["youngs_modulus"], Poisson=0.3)
    shaft = [rs.ShaftElement(L=float(L), idl=0.0, odl=float(d), material=steel, shear_effects=False,
                             rotary_inertia=True, gyroscopic=True) for L, d in zip(np.diff(NODES), DIAMETERS,
                                                                                   strict=True)]
    disks = [rs.DiskElement(n=node, m=m, Id=jt, Ip=jp) for node, m, jt, jp in DISKS]
    return rs.Rotor(shaft, disks, [])


if __name__ == "__main__":
    import sys

    if "--ross" in sys.argv:
        target = Path(__file__).resolve().parent / "compressor_ross" / "compressor_rotor.toml"
        compressor_ross().save(str(target))
        print(f"wrote {target}")
    rotor = compressor_structure()
    np.savez(TARGET, M=rotor.mass, K=rotor.stiffness, G=rotor.gyroscopic, nodes=rotor.nodes)
    body = modal_rotor(rotor, 2 * np.pi * 3000.0)
    print(f"wrote {TARGET}: {body.mass:.3f} kg, J_t {body.transverse_inertia:.4f}, J_p {body.polar_inertia:.5f} kg m^2")
    print("free-free bending [Hz]:", np.round(body.frequencies[::2] / (2 * np.pi), 1))
    print(f"mass centre {body.centre * 1e3:.1f} mm; nodes [mm]:", np.round(rotor.nodes * 1e3, 3))
