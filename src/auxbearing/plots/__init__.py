"""Figures: one function per figure, each returns a matplotlib Figure and changes nothing global."""
