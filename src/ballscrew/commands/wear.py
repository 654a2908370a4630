"""``ballscrew wear``: raceway wear, preload and drag torque over a load programme."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ballscrew.commands._common import CaseArg, Output, log, writes_results

ResumeOpt = Annotated[
    bool,
    typer.Option(
        "--resume/--restart",
        help="continue a stopped run from its checkpoint beside the results folder",
    ),
]


def checkpoint_path(out: Path) -> Path:
    """Checkpoint of a run writing to ``out``: ``.<name>.wear-state.npz`` beside the folder."""
    out = Path(out).expanduser().resolve()
    return out.parent / f".{out.name}.wear-state.npz"


@writes_results
def wear(case_file: CaseArg, resume: ResumeOpt = True, *, output: Output) -> None:
    """Wear profile of the screw raceway, preload and drag torque versus revolutions."""
    from ballscrew.analyses.wear import wear_life
    from ballscrew.errors import InputError
    from ballscrew.results.folder import writing

    case = output.load_case(case_file)
    with output.claim(case_file) as path, writing(path):
        state = checkpoint_path(output.out)
        if not resume:
            state.unlink(missing_ok=True)
        try:
            life = wear_life(case, checkpoint=state, resume=resume)
        except InputError as exc:
            if exc.field != "checkpoint":
                raise
            log.warning("the checkpoint %s is from another case; starting afresh", state)
            state.unlink(missing_ok=True)
            life = wear_life(case, checkpoint=state)
        # the final state, for a later run to continue from
        extra = {"state.npz": state.read_bytes()} if state.is_file() else {}
        output.write(life, case_file, extra)
        state.unlink(missing_ok=True)
