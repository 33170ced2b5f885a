"""Studies built from the core kernels: sweeps, comparisons, the paper's figures."""
