"""Regenerate ross_amb.json: ROSS's MagneticBearingElement for one magnetic bearing (a peer code's numbers).

Run with ROSS installed (``pip install 'auxbearing[ross]'``): ``python tests/regression/regenerate_ross_amb.py``.
The bearing is the one of tests/consistency/test_amb_circuit.py (232 turns, 400 mm^2 poles at 22.5 deg, 0.5 mm
gap, 1 A bias) under a PID of kp 6000 A/m, ki 1e5 A/(m s), kd 5 A s/m with unit sensor and amplifier gains and
a derivative filter far above the frequencies asked (an ideal PID, as our model with ideal lags).
"""

import json
import math
from pathlib import Path

import numpy as np

BEARING = {"g0": 0.5e-3, "i0": 1.0, "ag": 400e-6, "nw": 232, "alpha": math.pi / 8, "kp_pid": 6000.0,
           "ki_pid": 1e5, "kd_pid": 5.0, "n_f": 1e12, "k_amp": 1.0, "k_sense": 1.0}
FREQUENCIES = [10.0, 100.0, 300.0, 1000.0, 3000.0]  # rad/s


def main() -> None:
    import ross

    element = ross.MagneticBearingElement(n=0, frequency=np.array(FREQUENCIES), **BEARING)
    out = {"ross_version": ross.__version__, "bearing": BEARING, "frequencies_rad_s": FREQUENCIES,
           "ki_N_per_A": float(element.ki), "ks_N_per_m": float(element.ks),
           "kxx_N_per_m": [float(v) for v in element.kxx], "cxx_N_s_per_m": [float(v) for v in element.cxx],
           "kyy_N_per_m": [float(v) for v in element.kyy], "cyy_N_s_per_m": [float(v) for v in element.cyy]}
    path = Path(__file__).with_name("ross_amb.json")
    path.write_text(json.dumps(out, indent=1) + "\n")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
