"""The preconditioned CG on a window around the contact: the whole grid's solution (exact
convolution there, the preconditioner periodic on the window), and a return to the whole grid when
a cell outside the window penetrates."""

import numpy as np

from ballscrew.contact import DCFFTOperator, hertz, preconditioned, solve_normal, solve_normal_batch

E_STAR = 113.19e9


def sphere(n=128, side=6.0):
    """Hertz sphere R = 10 mm, W = 100 N on n × n cells, the box ``side`` × the contact radius."""
    reference = hertz(10e-3, 10e-3, E_STAR, 100.0)
    dx = side * reference.a / n
    x = dx * (np.arange(n) - n // 2)
    return (x[:, None] ** 2 + x[None, :] ** 2) / 20e-3, dx, reference


def test_window_gives_the_whole_grid_solution(monkeypatch):
    """Same iterations, pressures within the stop's error (1e-7 of p0, as pcg against pk), and the
    displacement handed back by the check is K ∗ p of the pressure."""
    gap, dx, reference = sphere()
    windows = []
    window = preconditioned._window
    monkeypatch.setattr(
        preconditioned, "_window", lambda p: windows.append(window(p)) or windows[-1]
    )
    windowed = solve_normal(gap, dx, dx, E_STAR, 100.0)
    used = [w for w in windows if w is not None]
    assert used and all((r.stop - r.start) * (c.stop - c.start) <= 0.5 * gap.size for r, c in used)
    monkeypatch.setattr(preconditioned, "WINDOW_MAX_FRACTION", 0.0)  # no window
    whole = solve_normal(gap, dx, dx, E_STAR, 100.0)
    assert windowed.iterations == whole.iterations and windowed.coarse_work == whole.coarse_work
    np.testing.assert_allclose(windowed.pressure, whole.pressure, atol=1e-7 * reference.p0)
    exact = DCFFTOperator(gap.shape, dx, dx, E_STAR).apply(windowed.pressure)
    np.testing.assert_array_equal(windowed.displacement, exact)


def test_window_is_used_on_a_large_box_only():
    gap = sphere()[0]
    p = np.zeros_like(gap)
    p[54:74, 50:78] = 1.0
    rows, cols = preconditioned._window(p)
    assert rows.start <= 50 and rows.stop >= 78 and cols.start <= 46 and cols.stop >= 82
    assert (rows.stop - rows.start) * (cols.stop - cols.start) <= 0.5 * gap.size
    assert preconditioned._window(np.ones_like(gap)) is None


def outgrown_seed(monkeypatch, gap):
    """No window margin, a warm start on an 8 × 8 patch of the 128² sphere (a quarter of the
    contact radius: the contact outgrows its window), and the list of the window checks' answers."""
    monkeypatch.setattr(preconditioned, "WINDOW_MARGIN", 0.0)
    monkeypatch.setattr(preconditioned, "WINDOW_MIN_MARGIN", 0)
    seed = np.zeros_like(gap)
    seed[60:68, 60:68] = 1.0
    cleared = []
    check = preconditioned._outside_clear
    monkeypatch.setattr(
        preconditioned, "_outside_clear", lambda *a: cleared.append(check(*a)) or cleared[-1]
    )
    return seed, cleared


def test_a_contact_that_outgrows_its_window_is_finished_on_the_whole_grid(monkeypatch):
    """A warm start on a patch of a quarter of the contact radius, no margin: the window's solution
    leaves cells outside it penetrating, so the solve goes on on the whole grid, and ends where
    a solve without a window does."""
    gap, dx, reference = sphere()
    seed, cleared = outgrown_seed(monkeypatch, gap)
    result = solve_normal(gap, dx, dx, E_STAR, 100.0, initial=seed)
    assert cleared == [False]
    whole = solve_normal(gap, dx, dx, E_STAR, 100.0, nested=False, method="pk")
    assert result.converged and result.displacement is not None
    np.testing.assert_allclose(result.pressure, whole.pressure, atol=1e-6 * reference.p0)


def test_batch_of_contacts_with_windows_of_two_sizes_equals_one_at_a_time():
    gap, dx, _ = sphere()
    gaps = np.stack([gap, gap, 2.0 * gap])
    loads = np.array([100.0, 60.0, 30.0])
    batch = solve_normal_batch(gaps, dx, dx, E_STAR, loads, precision="mixed")
    for g, load, together in zip(gaps, loads, batch, strict=True):
        alone = solve_normal(g, dx, dx, E_STAR, load, precision="mixed")
        assert together.iterations == alone.iterations
        np.testing.assert_array_equal(together.pressure, alone.pressure)


def test_only_the_contact_that_outgrows_its_window_goes_on_on_the_whole_grid(monkeypatch):
    """A batch of a contact seeded on a small patch (it outgrows its window) and one seeded with
    its own solution (it does not): the check fails for the first only, and each result is the
    one of its contact alone."""
    gap, dx, reference = sphere()
    settled = solve_normal(gap, dx, dx, E_STAR, 60.0).pressure
    seed, cleared = outgrown_seed(monkeypatch, gap)
    loads, initial = np.array([100.0, 60.0]), np.stack([seed, settled])
    batch = solve_normal_batch(np.stack([gap, gap]), dx, dx, E_STAR, loads, initial=initial)
    assert [list(c) for c in cleared] == [[False, True]]
    for b, together in enumerate(batch):
        alone = solve_normal(gap, dx, dx, E_STAR, loads[b], initial=initial[b])
        assert together.converged and together.iterations == alone.iterations
        np.testing.assert_allclose(together.pressure, alone.pressure, atol=1e-10 * reference.p0)
        exact = DCFFTOperator(gap.shape, dx, dx, E_STAR).apply(together.pressure)
        np.testing.assert_allclose(together.displacement, exact, rtol=0, atol=1e-12 * exact.max())


def brute_spans(mask):
    """First and last + 1 row and column holding a true cell, cell by cell (None if none)."""
    nx, ny = mask.shape[-2:]
    rows = [i for i in range(nx) if mask[..., i, :].any()]
    cols = [j for j in range(ny) if mask[..., :, j].any()]
    return ((rows[0], rows[-1] + 1), (cols[0], cols[-1] + 1)) if rows else None


def test_spans_of_a_mask_equal_a_brute_force_search():
    """Random masks of one grid and of a stack, empty, full, a single cell in each corner and
    the middle (the grids are not periodic: no span wraps around an edge)."""
    rng = np.random.default_rng(11)
    masks = [rng.random(shape) < density for shape in ((9, 13), (3, 7, 5), (1, 1), (4, 16, 16))
             for density in (0.0, 0.02, 0.3, 1.0)]  # fmt: skip
    for i, j in ((0, 0), (0, 12), (8, 0), (8, 12), (4, 6)):
        single = np.zeros((9, 13), dtype=bool)
        single[i, j] = True
        masks += [single, np.stack([np.zeros_like(single), single])]
    for mask in masks:
        assert preconditioned._spans(mask) == brute_spans(mask), mask.shape


def outside_clear_reference(h, u, p, windows, load):
    """The window check contact by contact: ḡ = mean of u + h over the contact cells of the window
    (0 under displacement control), and whether every cell outside the window has u + h ≥ ḡ."""
    clear = []
    for b, window in enumerate(windows):
        if window is None:
            clear.append(True)
            continue
        q = u[b] + h[b]
        contact = np.zeros(q.shape, dtype=bool)
        contact[window] = p[b][window] > 0.0
        g_bar = q[contact].mean() if load and contact.any() else 0.0
        outside = np.ones(q.shape, dtype=bool)
        outside[window] = False
        clear.append(bool(q[outside].min() >= g_bar))
    return clear


def test_outside_clear_of_a_batch_equals_the_check_contact_by_contact():
    """Windows of different sizes and places (one at an edge, one missing), pressures with and
    without cells in the window, under load and displacement control; both answers occur."""
    rng = np.random.default_rng(5)
    batch, shape = 7, (24, 20)
    windows = [(slice(2, 10), slice(3, 15)), None, (slice(0, 24), slice(12, 20)),
               (slice(5, 6), slice(5, 6)), (slice(10, 22), slice(0, 8)),
               (slice(4, 12), slice(4, 12)), (slice(8, 16), slice(2, 18))]  # fmt: skip
    h = rng.random((batch, *shape))
    u = rng.random((batch, *shape)) - 0.5
    p = np.where(rng.random((batch, *shape)) < 0.4, rng.random((batch, *shape)), 0.0)
    p[5] = 0.0  # no contact cell: ḡ = 0
    for b, window in enumerate(windows):  # outside the window u + h from about ḡ − 0.4 upwards
        if window is not None:
            outside = np.ones(shape, dtype=bool)
            outside[window] = False
            h[b][outside] += 0.3 * b - 0.6
    answers = []
    for load in (True, False):
        clear = preconditioned._outside_clear(h, u, p, windows, load)
        assert clear.dtype == bool and list(clear) == outside_clear_reference(
            h, u, p, windows, load
        )
        answers += list(clear)
    assert True in answers and False in answers
    none = preconditioned._outside_clear(h, u, p, [None] * batch, True)
    assert none.all()


def test_window_check_in_runs_of_one_contact_equals_the_whole_batch_at_once(monkeypatch):
    """The batch's window check taken one contact at a time (CHECK_CELLS = one grid) gives the
    answers of the reference, and a batch solve whose windows are checked so ends bit for bit
    where the check of the whole batch at once does."""
    from ballscrew import budget

    rng = np.random.default_rng(9)
    batch, shape = 6, (24, 20)
    windows = [(slice(2, 10), slice(3, 15)), None, (slice(0, 24), slice(12, 20)),
               (slice(5, 6), slice(5, 6)), None, (slice(8, 16), slice(2, 18))]  # fmt: skip
    h, u = rng.random((batch, *shape)), rng.random((batch, *shape)) - 0.5
    h[:, :8] -= 0.35
    p = np.where(rng.random((batch, *shape)) < 0.4, 1.0, 0.0)
    gap, dx, _ = sphere()
    gaps = np.stack([gap, 1.5 * gap, 2.0 * gap])
    solves, default = {}, budget.CHECK_CELLS
    for cells in (default, shape[0] * shape[1], gap.size):
        monkeypatch.setattr(budget, "CHECK_CELLS", cells)
        for load in (True, False):
            clear = preconditioned._outside_clear(h, u, p, windows, load)
            assert list(clear) == outside_clear_reference(h, u, p, windows, load)
        solves[cells] = solve_normal_batch(gaps, dx, dx, E_STAR, np.array([100.0, 80.0, 60.0]))
    assert budget.check_chunk(*gap.shape) == 1
    for one, whole in zip(solves[gap.size], solves[default], strict=True):
        np.testing.assert_array_equal(one.pressure, whole.pressure)
        np.testing.assert_array_equal(one.displacement, whole.displacement)


def test_window_check_memory_is_bounded_and_counted(monkeypatch):
    """The check of 16 contacts on 256² grids, in runs of 2 contacts, allocates at most
    CHECK_BYTES_PER_CELL per cell of a run (tracemalloc sees NumPy's buffers), which
    contact_batch_bytes adds to the solves' own; checked at once the same batch took ~ 8×."""
    import tracemalloc

    from ballscrew import budget

    batch, n = 16, 256
    h = np.ones((batch, n, n))
    u = np.zeros((batch, n, n))
    p = np.zeros((batch, n, n))
    p[:, 100:140, 100:140] = 1.0
    windows = [(slice(90, 150), slice(90, 150))] * batch
    windows[3] = None  # the windowed contacts are not all consecutive
    peaks = {}
    for cells in (2 * n * n, batch * n * n):
        monkeypatch.setattr(budget, "CHECK_CELLS", cells)
        tracemalloc.start()
        assert preconditioned._outside_clear(h, u, p, windows, True).all()
        peaks[cells] = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
    monkeypatch.setattr(budget, "CHECK_CELLS", 2 * n * n)
    counted = budget.contact_batch_bytes(batch, n, n) - batch * budget.contact_grid_bytes(n, n)
    assert peaks[2 * n * n] <= counted == budget.CHECK_BYTES_PER_CELL * 2 * n * n
    assert peaks[batch * n * n] > 4 * counted
