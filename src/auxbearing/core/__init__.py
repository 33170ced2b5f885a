"""Pure kernels on SI floats and numpy arrays: no units, no I/O, no printing."""
