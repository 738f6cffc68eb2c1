"""The report: results files -> Jinja templates -> one self-contained HTML -> PDF."""
