"""The machine description and its file.

Rotor, touchdown planes and mounts (:mod:`.model`), the file's parameter table and keys (:mod:`.params`,
:mod:`.keys`), the whole-document checks (:mod:`.check`) and the packing for the kernels (:mod:`.pack`,
for :mod:`auxbearing.core.machine`).
"""

#: Names ``auxbearing.machine`` held when it was one module, and where they live now (same room).
_MOVED_NAMES = {"machine_table": "files", "read_machine": "files", "machine_names": "files",
                "machine_document": "files"}


def __getattr__(name: str):
    """``from auxbearing.machine import Machine, read_machine`` as before the package (PEP 562)."""
    import importlib

    if name.startswith("__"):
        raise AttributeError(name)
    home = _MOVED_NAMES.get(name, "model")
    module = importlib.import_module(f"auxbearing.machine.{home}")
    if hasattr(module, name):
        return getattr(module, name)
    raise AttributeError(f"module 'auxbearing.machine' has no attribute {name!r}")
