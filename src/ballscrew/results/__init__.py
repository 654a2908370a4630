"""Writing results: atomic folders, summary.json, NetCDF fields, plots, report.html, exports."""

from ballscrew.results.export import export_results
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
    "export_results",
    "results_folder",
    "value",
    "write_netcdf",
    "write_report",
    "write_results",
    "write_summary",
]
