#!/usr/bin/python3
"""Renders an OBJ frame written by `exactgeo-cloth --output` to a PNG picture: the faces
under `g cloth` in blue, darker the smaller they are (so that remeshing shows: a triangle
a quarter of the largest one's area or less is darker, a sixteenth or less darkest), the
others (`g obstacle`) in grey, flat shaded, framed on the cloth, with a caption below.

  scripts/render-obj.py FRAME.obj OUT.png [--view AZIMUTH ELEVATION] [--up x|y|z]
                        [--size PIXELS] [--grow GROW] [--caption TEXT]

The rasteriser and the view are render-marked-ply.py's (orthographic, azimuth about the
vertical axis, elevation above the horizontal plane). `--grow` widens the frame around the
cloth's box. Needs numpy and Pillow (Debian: python3-numpy, python3-pil).
"""

import argparse
import importlib.util
import pathlib

import numpy as np
from PIL import Image, ImageDraw, ImageFont

_spec = importlib.util.spec_from_file_location(
    "render_marked_ply", pathlib.Path(__file__).with_name("render-marked-ply.py"))
marked = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(marked)

CLOTH = [(110, 160, 235), (60, 110, 200), (25, 55, 140)]  # by size, largest first
OBSTACLE = (205, 205, 200)


def read_obj(path):
    """Vertices (n, 3), triangles [(a, b, c)], and whether each is the cloth's."""
    points, faces, cloth, group = [], [], [], "cloth"
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                points.append([float(x) for x in words[1:4]])
            elif words[0] == "g":
                group = words[1] if len(words) > 1 else ""
            elif words[0] == "f":
                faces.append(tuple(int(w.split("/")[0]) - 1 for w in words[1:4]))
                cloth.append(group == "cloth")
    return np.array(points), faces, cloth


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("obj")
    parser.add_argument("png")
    parser.add_argument("--view", nargs=2, type=float, default=(-60.0, 25.0),
                        metavar=("AZIMUTH", "ELEVATION"))
    parser.add_argument("--up", choices="xyz", default="y")
    parser.add_argument("--size", type=int, default=480)
    parser.add_argument("--grow", type=float, default=1.15)
    parser.add_argument("--caption", default="")
    args = parser.parse_args()

    points, faces, cloth = read_obj(args.obj)
    frame = marked.view_frame(*args.view, args.up)
    view = points @ frame.T
    cloth_vertices = sorted({v for f, c in zip(faces, cloth) if c for v in f})
    framed = view[cloth_vertices] if cloth_vertices else view
    centre = (framed.min(axis=0) + framed.max(axis=0)) / 2
    half = args.grow * (framed.max(axis=0) - framed.min(axis=0))[:2].max() / 2
    lower, upper = centre[:2] - half, centre[:2] + half
    side = args.size * marked.SUPERSAMPLE
    scale = side / (upper - lower).max()
    width = height = side
    screen = np.empty((len(points), 2))
    screen[:, 0] = (view[:, 0] - lower[0]) * scale
    screen[:, 1] = height - (view[:, 1] - lower[1]) * scale
    areas = [np.linalg.norm(np.cross(points[b] - points[a], points[c] - points[a]))
             for a, b, c in faces]
    largest = max((area for area, c in zip(areas, cloth) if c), default=1.0)
    colours = []
    for area, c in zip(areas, cloth):
        level = 0 if area > largest / 4 else 1 if area > largest / 16 else 2
        colours.append(CLOTH[level] if c else OBSTACLE)
    triangles, shaded = marked.shade(points, faces, colours, frame)
    image, _ = marked.rasterise(screen, view[:, 2], triangles, shaded, width, height)
    picture = Image.fromarray(image.clip(0, 255).astype(np.uint8))
    picture = picture.resize((width // marked.SUPERSAMPLE, height // marked.SUPERSAMPLE),
                             Image.LANCZOS)
    if args.caption:
        font = ImageFont.load_default()
        out = Image.new("RGB", (picture.width, picture.height + 20), "white")
        out.paste(picture, (0, 0))
        ImageDraw.Draw(out).text((8, picture.height + 4), args.caption, fill=(0, 0, 0), font=font)
        picture = out
    picture.save(args.png, optimize=True)


if __name__ == "__main__":
    main()
