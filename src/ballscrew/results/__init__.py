"""Writing results: atomic folders, summary.json, NetCDF fields, plots and report.html."""

from ballscrew.results.folder import check_output_folder, results_folder
from ballscrew.results.report import Section, write_report
from ballscrew.results.summary import value, write_summary

__all__ = [
    "Section",
    "check_output_folder",
    "results_folder",
    "value",
    "write_report",
    "write_summary",
]
