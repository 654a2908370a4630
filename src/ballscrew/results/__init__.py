"""Writing results: atomic folders, summary.json, NetCDF fields, plots and report.html."""

from ballscrew.results.folder import (
    ResultsWriteError,
    check_output_folder,
    claim_output,
    results_folder,
    write_netcdf,
)
from ballscrew.results.report import Section, write_report
from ballscrew.results.summary import value, write_summary
from ballscrew.results.writer import write_results

__all__ = [
    "ResultsWriteError",
    "Section",
    "check_output_folder",
    "claim_output",
    "results_folder",
    "value",
    "write_netcdf",
    "write_report",
    "write_results",
    "write_summary",
]
