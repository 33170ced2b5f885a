"""The analyses of a bearing and a machine: contact, statics, drop, coast-down, heat, life and whirl.

Each returns data (dictionaries, xarray datasets) and draws nothing; figures live in :mod:`auxbearing.plots`.
"""
