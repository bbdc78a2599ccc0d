"""Figures in one style: drawn without a display (the Agg backend), sizes in inches, written at 120 dpi after
tight_layout (unless the figure has a layout of its own), and closed once written.

    from granmc.plotting import pyplot, save
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ...
    save(fig, "figure.png")
"""
DPI = 120


def pyplot():
    """matplotlib.pyplot on the Agg backend (imported on first use, so that reading results needs no matplotlib)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def save(fig, path):
    """Lays the figure out, writes it to `path` (the format from the suffix) and closes it."""
    if fig.get_layout_engine() is None:  # a figure made with constrained_layout keeps its own
        fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    pyplot().close(fig)
