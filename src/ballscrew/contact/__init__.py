"""Normal contact of smooth or rough bodies: Hertz closed forms and the discrete half-space solver.

1. :func:`hertz` (exact, Johnson 1985) and :func:`hamrock_brewe` (curve fits, 1983) for the
   quadratic gap h = x²/(2 rx) + y²/(2 ry).
2. :func:`solve_normal` (load given) and :func:`solve_normal_displacement` (approach given): the
   Polonsky & Keer (1999) conjugate-gradient solver on any gap h(x, y) sampled on a cell-centred
   grid, with Love's (1929) cell coefficients and DC-FFT convolution (Liu, Wang & Liu 2000).
   :func:`solve_normal_batch`: many contacts on one grid in one call (batched FFTs). The solver
   is chosen from :data:`NORMAL_SOLVERS` (``method``): the preconditioned, nested-grid CG
   (``"pcg"``, after Vollebregt 2014) or the plain Polonsky & Keer CG (``"pk"``).
3. :func:`solve_contact`: sizes the grid from the Hertz estimate, warm-starts from the Hertz
   pressure and enlarges the box until the pressure vanishes on its edge; :func:`solve_contacts`
   does it for many contacts, those on grids of equal cell counts in one batched call, each
   contact at its load and at further (smaller) loads on the same grid if asked.
"""

from ballscrew.contact.batch import solve_normal_batch
from ballscrew.contact.convolution import DCFFTOperator, direct_convolution, wraparound_kernel
from ballscrew.contact.grid import (
    DEFAULT_BOX_FACTOR,
    DEFAULT_CELLS_ACROSS,
    ContactRequest,
    GridContactResult,
    cell_centres,
    grid_cells,
    solve_contact,
    solve_contacts,
)
from ballscrew.contact.hertz import HertzContact, hamrock_brewe, hertz
from ballscrew.contact.influence import love_coefficient, love_coefficients
from ballscrew.contact.polonsky_keer import (
    DEFAULT_MAX_ITERATIONS,
    DEFAULT_METHOD,
    DEFAULT_TOLERANCE,
    NORMAL_SOLVERS,
    solve_normal,
    solve_normal_displacement,
)
from ballscrew.contact.result import ContactResult, contact_semi_axes

__all__ = [
    "DEFAULT_BOX_FACTOR",
    "DEFAULT_CELLS_ACROSS",
    "DEFAULT_MAX_ITERATIONS",
    "DEFAULT_METHOD",
    "DEFAULT_TOLERANCE",
    "NORMAL_SOLVERS",
    "ContactRequest",
    "ContactResult",
    "DCFFTOperator",
    "GridContactResult",
    "HertzContact",
    "cell_centres",
    "contact_semi_axes",
    "direct_convolution",
    "grid_cells",
    "hamrock_brewe",
    "hertz",
    "love_coefficient",
    "love_coefficients",
    "solve_contact",
    "solve_contacts",
    "solve_normal",
    "solve_normal_batch",
    "solve_normal_displacement",
    "wraparound_kernel",
]
