"""A log-log line plot as a standalone SVG, standard library only (the benchmark scripts'
figures in docs/)."""
import math

PALETTE = ["#1b7837", "#b2182b", "#2166ac", "#e08214", "#762a83", "#5aae61", "#999999",
           "#ef8a62"]
DASHES = ["", "6,4", "2,3"]


def loglog_svg(series, x_label, y_label, title=None):
    """series: {name: [(x, y), ...]} with positive values; returns the SVG text.

    Names of the form "group, variant" share a colour per group and a dash pattern per
    variant (for example "exact, uniform" and "exact, near"). Ticks at every power of ten
    (and at 2 and 5 times it when the axis spans two decades or fewer); the legend sits
    right of the plot, as wide as its longest name."""
    groups = list(dict.fromkeys(name.rsplit(", ", 1)[0] for name in sorted(series)))
    variants = list(dict.fromkeys(name.rsplit(", ", 1)[1] if ", " in name else ""
                                  for name in sorted(series)))
    longest = max(len(name) for name in series)
    left, bottom, top = 74, 50, 40 if title else 20
    right = 60 + 7 * longest
    width, height = 520 + right, 380
    xs = [math.log10(x) for s in series.values() for x, _ in s]
    ys = [math.log10(y) for s in series.values() for _, y in s]
    x_lo, x_hi = math.floor(min(xs)), max(math.ceil(max(xs)), math.floor(min(xs)) + 1)
    y_lo, y_hi = math.floor(min(ys)), max(math.ceil(max(ys)), math.floor(min(ys)) + 1)
    pw, ph = width - left - right, height - top - bottom

    def sx(v):
        return left + (math.log10(v) - x_lo) / (x_hi - x_lo) * pw

    def sy(v):
        return top + ph - (math.log10(v) - y_lo) / (y_hi - y_lo) * ph

    def ticks(lo, hi):
        steps = (1, 2, 5) if hi - lo <= 2 else (1,)
        return [m * 10.0 ** e for e in range(lo, hi + 1) for m in steps
                if m * 10.0 ** e <= 10.0 ** hi]

    def label(v):
        e = math.floor(math.log10(v) + 1e-9)
        m = round(v / 10.0 ** e)
        if -2 <= e <= 4:
            return f"{v:g}"
        return f"{m}e{e}" if m != 1 else f"1e{e}"

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'font-family="sans-serif" font-size="12">',
           f'<rect width="{width}" height="{height}" fill="white"/>']
    if title:
        out.append(f'<text x="{left + pw / 2}" y="22" text-anchor="middle" font-size="14" '
                   f'font-weight="bold">{title}</text>')
    for v in ticks(x_lo, x_hi):
        x = sx(v)
        out.append(f'<line x1="{x:.1f}" y1="{top}" x2="{x:.1f}" y2="{top + ph}" stroke="#eee"/>')
        out.append(f'<text x="{x:.1f}" y="{top + ph + 16}" text-anchor="middle">{label(v)}</text>')
    for v in ticks(y_lo, y_hi):
        y = sy(v)
        out.append(f'<line x1="{left}" y1="{y:.1f}" x2="{left + pw}" y2="{y:.1f}" stroke="#eee"/>')
        out.append(f'<text x="{left - 6}" y="{y + 4:.1f}" text-anchor="end">{label(v)}</text>')
    out.append(f'<rect x="{left}" y="{top}" width="{pw}" height="{ph}" fill="none" stroke="#888"/>')
    out.append(f'<text x="{left + pw / 2}" y="{height - 12}" text-anchor="middle">{x_label}</text>')
    out.append(f'<text x="16" y="{top + ph / 2}" transform="rotate(-90 16 {top + ph / 2})" '
               f'text-anchor="middle">{y_label}</text>')
    for i, (name, points) in enumerate(sorted(series.items())):
        group = name.rsplit(", ", 1)[0]
        variant = name.rsplit(", ", 1)[1] if ", " in name else ""
        colour = PALETTE[groups.index(group) % len(PALETTE)]
        dash = DASHES[variants.index(variant) % len(DASHES)]
        style = f' stroke-dasharray="{dash}"' if dash else ""
        points = sorted(points)
        path = " ".join(f"{sx(x):.1f},{sy(y):.1f}" for x, y in points)
        out.append(f'<polyline points="{path}" fill="none" stroke="{colour}" stroke-width="2"'
                   f'{style}/>')
        for x, y in points:
            out.append(f'<circle cx="{sx(x):.1f}" cy="{sy(y):.1f}" r="3" fill="{colour}"/>')
        y = top + 10 + 18 * i
        out.append(f'<line x1="{width - right + 14}" y1="{y}" x2="{width - right + 40}" y2="{y}" '
                   f'stroke="{colour}" stroke-width="2"{style}/>')
        out.append(f'<text x="{width - right + 46}" y="{y + 4}">{name}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"
