"""Data files: the materials and bearings catalogues, each entry with its source."""
