"""Build-time generators of the shipped curve table (scipy's ``_precompute`` pattern).

Nothing here is imported when the package runs: ``python -m torsional_contact.curves`` runs
``build_table.main``, which solves on every panel and rewrites ``curves/monotonic_curves.json``.
"""
