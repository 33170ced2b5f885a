"""Measured drops: read, preprocess, turn orbits into force and stress, fit the unknown inputs."""
