"""Validation cases, one module per family; see :mod:`cosim.validation`."""
