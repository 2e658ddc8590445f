"""Saving a matplotlib figure atomically (a temporary file renamed into place), so that an
interrupted plot never leaves a half-written PNG; shared by the plot scripts."""
import matplotlib.pyplot as plt


def save_figure(figure, output, dpi=120):
    temporary = output.with_suffix(".tmp.png")
    figure.savefig(temporary, dpi=dpi)
    temporary.replace(output)
    plt.close(figure)
    print(f"wrote {output}")
