"""The machine description and its file.

Rotor, touchdown planes and mounts (:mod:`.model`), the file's parameter table and keys (:mod:`.params`,
:mod:`.keys`), the whole-document checks (:mod:`.check`) and the packing for the kernels (:mod:`.pack`,
for :mod:`auxbearing.core.machine`).
"""
