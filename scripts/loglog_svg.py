"""A log-log line plot as a standalone SVG, standard library only (the benchmark scripts'
figures in docs/)."""
import math

PALETTE = ["#1b7837", "#b2182b", "#5aae61", "#ef8a62", "#762a83", "#2166ac", "#999999",
           "#e08214"]


def loglog_svg(series, x_label, y_label):
    """series: {name: [(x, y), ...]} with positive values; returns the SVG text."""
    width, height, left, bottom, top, right = 640, 360, 70, 50, 20, 190
    xs = [math.log10(x) for s in series.values() for x, _ in s]
    ys = [math.log10(y) for s in series.values() for _, y in s]
    x_lo, x_hi = math.floor(min(xs)), max(math.ceil(max(xs)), math.floor(min(xs)) + 1)
    y_lo, y_hi = math.floor(min(ys)), max(math.ceil(max(ys)), math.floor(min(ys)) + 1)
    pw, ph = width - left - right, height - top - bottom

    def sx(v):
        return left + (math.log10(v) - x_lo) / (x_hi - x_lo) * pw

    def sy(v):
        return top + ph - (math.log10(v) - y_lo) / (y_hi - y_lo) * ph

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'font-family="sans-serif" font-size="11">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           f'<rect x="{left}" y="{top}" width="{pw}" height="{ph}" fill="none" stroke="#888"/>']
    for e in range(x_lo, x_hi + 1):
        x = left + (e - x_lo) / (x_hi - x_lo) * pw
        out.append(f'<text x="{x}" y="{top + ph + 15}" text-anchor="middle">1e{e}</text>')
    for e in range(y_lo, y_hi + 1):
        y = top + ph - (e - y_lo) / (y_hi - y_lo) * ph
        out.append(f'<text x="{left - 6}" y="{y + 4}" text-anchor="end">1e{e}</text>')
    out.append(f'<text x="{left + pw / 2}" y="{height - 12}" text-anchor="middle">{x_label}</text>')
    out.append(f'<text x="16" y="{top + ph / 2}" transform="rotate(-90 16 {top + ph / 2})" '
               f'text-anchor="middle">{y_label}</text>')
    for i, (name, points) in enumerate(sorted(series.items())):
        colour = PALETTE[i % len(PALETTE)]
        points = sorted(points)
        path = " ".join(f"{sx(x):.1f},{sy(y):.1f}" for x, y in points)
        out.append(f'<polyline points="{path}" fill="none" stroke="{colour}" stroke-width="2"/>')
        for x, y in points:
            out.append(f'<circle cx="{sx(x):.1f}" cy="{sy(y):.1f}" r="3" fill="{colour}"/>')
        y = top + 10 + 16 * i
        out.append(f'<line x1="{width - right + 10}" y1="{y}" x2="{width - right + 30}" y2="{y}" '
                   f'stroke="{colour}" stroke-width="2"/>')
        out.append(f'<text x="{width - right + 35}" y="{y + 4}">{name}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"
