#!/usr/bin/python3
"""Renders a PLY file written by `exactgeo info --mark` or `exactgeo ccd-mesh --mark` to a
PNG picture: the faces in their colours, flat shaded, the coloured edges and vertices on
top, a ring around each small group of marked faces that faces the viewer (a degenerate
face has no area to see), and the legend from the file's comments below.

  scripts/render-marked-ply.py MARKED.ply OUT.png [--view AZIMUTH ELEVATION] [--up x|y|z]
                               [--size PIXELS] [--focus GROW]

The picture is for looking at, not a predicate: quads are drawn as two triangles and
depth is compared in floating point. Orthographic view from the direction given by the
azimuth (degrees about the vertical axis, from +x towards +y) and the elevation (degrees
above the horizontal plane); `--up` names the vertical axis (default z). `--focus` frames
the marked elements (coloured edges, vertices in a colour other than the commonest) and
their surroundings, their box grown GROW times, instead of the whole mesh. Needs numpy and
Pillow (Debian: python3-numpy, python3-pil).
"""

import argparse
import math
import re

import numpy as np
from PIL import Image, ImageDraw, ImageFont

SUPERSAMPLE = 2
LEGEND = re.compile(r"^comment legend (\w+) (\d+) (\d+) (\d+) #[0-9a-f]{6}: (.*) \((\d+)\)$")


def read_marked_ply(path):
    """Vertices (n, 3), vertex colours or None, faces [corner lists], face colours (m, 3),
    edges (k, 2), edge colours (k, 3), legend [(element, rgb, meaning, count)]."""
    with open(path) as f:
        lines = f.read().splitlines()
    legend, counts, vertex_colours = [], {}, False
    element, end = None, lines.index("end_header")
    for line in lines[:end]:
        match = LEGEND.match(line)
        if match:
            rgb = tuple(int(match.group(k)) for k in (2, 3, 4))
            legend.append((match.group(1), rgb, match.group(5), int(match.group(6))))
        words = line.split()
        if words[:1] == ["element"]:
            element = words[1]
            counts[element] = int(words[2])
        if element == "vertex" and line == "property uchar red":
            vertex_colours = True
    rows = iter(lines[end + 1:])
    vertices = [next(rows).split() for _ in range(counts.get("vertex", 0))]
    faces = [next(rows).split() for _ in range(counts.get("face", 0))]
    edges = [next(rows).split() for _ in range(counts.get("edge", 0))]
    points = np.array([[float(x) for x in v[:3]] for v in vertices])
    colours = np.array([[int(x) for x in v[3:6]] for v in vertices]) if vertex_colours else None
    corners = [[int(x) for x in f[1:1 + int(f[0])]] for f in faces]
    face_colours = np.array([[int(x) for x in f[1 + int(f[0]):4 + int(f[0])]] for f in faces])
    edge_list = np.array([[int(x) for x in e[:2]] for e in edges], dtype=int).reshape(-1, 2)
    edge_colours = np.array([[int(x) for x in e[2:5]] for e in edges]).reshape(-1, 3)
    return points, colours, corners, face_colours, edge_list, edge_colours, legend


def view_frame(azimuth, elevation, up_axis):
    """Rows: the picture's right, up and towards-the-viewer directions in model coordinates."""
    a, e = math.radians(azimuth), math.radians(elevation)
    towards = np.array([math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)])
    right = np.array([-math.sin(a), math.cos(a), 0.0])
    up = np.cross(towards, right)
    frame = np.array([right, up, towards])
    # Model axes in the order (horizontal 1, horizontal 2, vertical).
    order = {"x": [1, 2, 0], "y": [2, 0, 1], "z": [0, 1, 2]}[up_axis]
    permutation = np.zeros((3, 3))
    for k, axis in enumerate(order):
        permutation[k, axis] = 1.0
    return frame @ permutation


def rasterise(screen, depth, corners, colours, width, height):
    """Flat-shaded triangles with a depth buffer; larger depth is nearer."""
    image = np.full((height, width, 3), 255.0)
    zbuffer = np.full((height, width), -np.inf)
    for (a, b, c), colour in zip(corners, colours):
        pa, pb, pc = screen[a], screen[b], screen[c]
        x0, x1 = int(max(0, math.floor(min(pa[0], pb[0], pc[0])))), \
            int(min(width - 1, math.ceil(max(pa[0], pb[0], pc[0]))))
        y0, y1 = int(max(0, math.floor(min(pa[1], pb[1], pc[1])))), \
            int(min(height - 1, math.ceil(max(pa[1], pb[1], pc[1]))))
        area = (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pc[0] - pa[0]) * (pb[1] - pa[1])
        if x1 < x0 or y1 < y0 or area == 0:
            continue
        xs, ys = np.meshgrid(np.arange(x0, x1 + 1) + 0.5, np.arange(y0, y1 + 1) + 0.5)
        w0 = ((pb[0] - xs) * (pc[1] - ys) - (pc[0] - xs) * (pb[1] - ys)) / area
        w1 = ((pc[0] - xs) * (pa[1] - ys) - (pa[0] - xs) * (pc[1] - ys)) / area
        w2 = 1.0 - w0 - w1
        inside = (w0 >= 0) & (w1 >= 0) & (w2 >= 0)
        z = w0 * depth[a] + w1 * depth[b] + w2 * depth[c]
        window = zbuffer[y0:y1 + 1, x0:x1 + 1]
        nearer = inside & (z > window)
        window[nearer] = z[nearer]
        image[y0:y1 + 1, x0:x1 + 1][nearer] = colour
    return image, zbuffer


def shade(points, corners, colours, frame):
    """Each face's colour dimmed by the angle between its normal and the view."""
    light = frame[2] * 0.8 + frame[1] * 0.45 + frame[0] * 0.2
    light /= np.linalg.norm(light)
    triangles, shaded = [], []
    for face, colour in zip(corners, colours):
        for k in range(1, len(face) - 1):  # a fan: for the picture only
            tri = (face[0], face[k], face[k + 1])
            normal = np.cross(points[tri[1]] - points[tri[0]], points[tri[2]] - points[tri[0]])
            length = np.linalg.norm(normal)
            lambert = abs(normal @ light) / length if length > 0 else 0.0
            triangles.append(tri)
            shaded.append(np.asarray(colour, float) * (0.45 + 0.55 * lambert))
    return triangles, shaded


def draw_lines(image, zbuffer, screen, depth, segments, colours, thickness):
    height, width = zbuffer.shape
    bias = 1e-3 * (depth.max() - depth.min() + 1e-300)
    for (a, b), colour in zip(segments, colours):
        steps = int(max(abs(screen[b] - screen[a]))) * 2 + 2
        for t in np.linspace(0.0, 1.0, steps):
            x, y = screen[a] + t * (screen[b] - screen[a])
            z = depth[a] + t * (depth[b] - depth[a])
            for dx in range(-thickness, thickness + 1):
                for dy in range(-thickness, thickness + 1):
                    i, j = int(y) + dy, int(x) + dx
                    if 0 <= i < height and 0 <= j < width and z + bias >= zbuffer[i, j]:
                        image[i, j] = colour


def callouts(image, zbuffer, screen, depth, corners, face_colours, legend, radius):
    """Rings around the faces of the rarer saturated colours (at most 20 faces of a colour),
    one per group, where the face's centre is not hidden."""
    height, width = zbuffer.shape
    bias = 1e-2 * (depth.max() - depth.min() + 1e-300)
    # The saturated colours are the findings; the pale ones mean "nothing to see".
    rare = {entry[1] for entry in legend if 0 < entry[3] <= 20 and min(entry[1]) < 160}
    draw = ImageDraw.Draw(image)
    ringed = []
    for face, colour in zip(corners, face_colours):
        if tuple(colour) not in rare:
            continue
        x, y = screen[face].mean(axis=0)
        z = depth[face].mean()
        i, j = int(y), int(x)
        if not (0 <= i < height and 0 <= j < width) or z + bias < zbuffer[i, j]:
            continue
        if any(math.hypot(x - u, y - v) < 4 * radius and c == tuple(colour)
               for u, v, c in ringed):
            continue  # one ring for a group of faces of one colour
        ringed.append((x, y, tuple(colour)))
        box = [x - radius, y - radius, x + radius, y + radius]
        draw.ellipse(box, outline=(0, 0, 0), width=3 * SUPERSAMPLE)
        draw.ellipse(box, outline=tuple(int(c) for c in colour), width=SUPERSAMPLE)


def legend_strip(legend, width):
    font = ImageFont.load_default()
    strip = Image.new("RGB", (width, 16 * len(legend) + 8), "white")
    draw = ImageDraw.Draw(strip)
    for k, (element, rgb, meaning, count) in enumerate(legend):
        y = 4 + 16 * k
        draw.rectangle([8, y + 1, 22, y + 12], fill=rgb, outline=(0, 0, 0))
        draw.text((30, y), f"{element}: {meaning} ({count})", fill=(0, 0, 0), font=font)
    return strip


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("ply")
    parser.add_argument("png")
    parser.add_argument("--view", nargs=2, type=float, default=(-60.0, 25.0),
                        metavar=("AZIMUTH", "ELEVATION"))
    parser.add_argument("--up", choices="xyz", default="z")
    parser.add_argument("--size", type=int, default=640)
    parser.add_argument("--focus", type=float, default=None, metavar="GROW")
    args = parser.parse_args()

    points, vertex_colours, corners, face_colours, edges, edge_colours, legend = \
        read_marked_ply(args.ply)
    frame = view_frame(*args.view, args.up)
    view = points @ frame.T
    framed = view
    if args.focus is not None:
        marked = set(edges.flatten())
        if vertex_colours is not None:
            values, counts = np.unique(vertex_colours, axis=0, return_counts=True)
            plain = values[np.argmax(counts)]
            marked |= {v for v in range(len(points)) if (vertex_colours[v] != plain).any()}
        if marked:
            framed = view[sorted(marked)]
            centre = (framed.min(axis=0) + framed.max(axis=0)) / 2
            half = args.focus * (framed.max(axis=0) - framed.min(axis=0)).max() / 2
            framed = np.array([centre - half, centre + half])  # a square frame
    lower, upper = framed[:, :2].min(axis=0), framed[:, :2].max(axis=0)
    side = args.size * SUPERSAMPLE
    scale = 0.92 * side / max(upper - lower)
    extent = (upper - lower) * scale
    width, height = int(extent[0] / 0.92) + 1, int(extent[1] / 0.92) + 1
    screen = np.empty((len(points), 2))
    screen[:, 0] = (view[:, 0] - lower[0]) * scale + 0.04 * width
    screen[:, 1] = height - ((view[:, 1] - lower[1]) * scale + 0.04 * height)
    depth = view[:, 2]

    triangles, shaded = shade(points, corners, face_colours, frame)
    image, zbuffer = rasterise(screen, depth, triangles, shaded, width, height)
    draw_lines(image, zbuffer, screen, depth, edges, edge_colours, SUPERSAMPLE)
    if vertex_colours is not None:
        # Vertices in a colour other than the commonest one (the unmarked) as dots.
        values, counts = np.unique(vertex_colours, axis=0, return_counts=True)
        plain = values[np.argmax(counts)]
        marked = [v for v in range(len(points)) if (vertex_colours[v] != plain).any()]
        dots = [(v, v) for v in marked]
        draw_lines(image, zbuffer, screen, depth, dots, vertex_colours[marked], 2 * SUPERSAMPLE)
    picture = Image.fromarray(image.clip(0, 255).astype(np.uint8))
    callouts(picture, zbuffer, screen, depth, corners, face_colours, legend, 14 * SUPERSAMPLE)
    picture = picture.resize((width // SUPERSAMPLE, height // SUPERSAMPLE), Image.LANCZOS)
    font = ImageFont.load_default()
    text_width = max((font.getlength(f"{e}: {m} ({c})") for e, _, m, c in legend), default=0)
    width = max(picture.width, int(text_width) + 40)
    strip = legend_strip(legend, width)
    out = Image.new("RGB", (width, picture.height + strip.height), "white")
    out.paste(picture, ((width - picture.width) // 2, 0))
    out.paste(strip, (0, picture.height))
    out.save(args.png, optimize=True)


if __name__ == "__main__":
    main()
