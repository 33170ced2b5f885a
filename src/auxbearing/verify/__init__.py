"""Verification of a machine's touchdown bearings: cases, criteria, candidates, a recommendation."""
