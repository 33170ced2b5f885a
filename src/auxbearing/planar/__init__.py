"""The planar drop rig: one touchdown plane at the rotor's mass centre, tilt and axial motion locked.

The source paper's test rig (Sec. II.D, Table II) and any rig like it, as an ordinary machine
(:func:`~auxbearing.planar.rig.planar_machine`) with its drop parameters (:mod:`~auxbearing.planar.params`).
The ``drop`` command without ``--machine``, the measured-drop fit (:mod:`auxbearing.experiment`) and the
paper's study (:mod:`auxbearing.paper`) stand on it.
"""
