"""The geometry of the summary's charts, for the templates to draw as inline SVG.

Contents:
    Bar, Chart                      rectangles and their labels, in SVG user units
    histogram_chart(counts)         vertical bars: students per band of percent
    share_chart(groups)             horizontal bars: a share (0–1) per labelled row, rows under headings

Coordinates are computed here rather than in the templates, so the templates only place
values (escaped as every other value) and stay readable.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

__all__ = ["Bar", "Chart", "histogram_chart", "share_chart"]


@dataclass(frozen=True)
class Bar:
    """One bar: its rectangle, the text at its end (``value``) and its axis label."""

    x: float
    y: float
    width: float
    height: float
    label: str
    value: str


@dataclass(frozen=True)
class Chart:
    """A whole chart: its size, its bars, the plot area's edges, its gridlines and its row headings
    (each a (position, text))."""

    width: float
    height: float
    bars: tuple[Bar, ...]
    left: float
    top: float
    right: float
    bottom: float
    grid: tuple[tuple[float, str], ...]
    headings: tuple[tuple[float, str], ...] = ()


def histogram_chart(counts: Sequence[int], *, width: float = 640, height: float = 240) -> Chart:
    """Vertical bars for ``counts``, one per equal band of 0–100 %.

    >>> chart = histogram_chart([0, 1, 3, 0, 0, 0, 0, 0, 0, 2])
    >>> [bar.label for bar in chart.bars][:3], chart.bars[2].value, chart.bars[2].height > chart.bars[9].height
    (['0–10', '10–20', '20–30'], '3', True)
    """
    left, right, top, bottom = 40.0, width - 10.0, 16.0, height - 28.0
    bins = len(counts)
    step = (right - left) / bins
    scale = max(max(counts, default=0), 1)
    ticks = _ticks(scale)
    bars = []
    for index, count in enumerate(counts):
        bar_height = (bottom - top) * count / ticks[-1]
        low, high = 100 * index // bins, 100 * (index + 1) // bins
        bars.append(
            Bar(left + index * step + 2, bottom - bar_height, step - 4, bar_height, f"{low}–{high}", str(count))
        )
    grid = tuple((bottom - (bottom - top) * tick / ticks[-1], str(tick)) for tick in ticks)
    return Chart(width, height, tuple(bars), left, top, right, bottom, grid)


def share_chart(
    groups: Sequence[tuple[str, Sequence[tuple[str, float]]]], *, width: float = 720, row: float = 18
) -> Chart:
    """Horizontal bars, one row per (label, share) with the share (0–1) as the bar's length,
    the rows of each group under its heading.

    >>> chart = share_chart([("The plane pendulum", [("lagrangian", 0.5), ("motion", 1.0)])])
    >>> chart.bars[0].width * 2 == chart.bars[1].width, chart.bars[0].value, chart.headings[0][1]
    (True, '50%', 'The plane pendulum')
    """
    longest = max((len(label) for _, rows in groups for label, _ in rows), default=0)
    left = min(20.0 + 6.6 * longest, width / 2)  # 6.6: a character's width in 11px monospace
    right, top = width - 48.0, 26.0
    bars, headings, y = [], [], top
    for heading, rows in groups:
        headings.append((y + row - 4, heading))
        y += row + 2
        for label, share in rows:
            length = (right - left) * min(max(share, 0.0), 1.0)
            bars.append(Bar(left, y + 3, length, row - 6, label, f"{share:.0%}"))
            y += row
        y += 6
    grid = tuple((left + (right - left) * tick / 100, f"{tick}%") for tick in (0, 25, 50, 75, 100))
    return Chart(width, y + 4, tuple(bars), left, top, right, y, grid, tuple(headings))


def _ticks(largest: int) -> list[int]:
    """Whole-number gridlines from 0 to at least ``largest``, at most about five of them.

    >>> _ticks(3), _ticks(7), _ticks(40)
    ([0, 1, 2, 3], [0, 2, 4, 6, 8], [0, 10, 20, 30, 40])
    """
    for step in (1, 2, 5, 10, 20, 25, 50, 100, 200, 250, 500, 1000):
        if largest / step <= 5:
            break
    else:
        step = -(-largest // 5)
    top = -(-largest // step) * step
    return list(range(0, top + 1, step))
