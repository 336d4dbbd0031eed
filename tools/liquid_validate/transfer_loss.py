#!/usr/bin/env python3
"""How much of a sloshing tank's first mode one particle -> grid -> particle transfer keeps, on the
CPU: the mode's potential-flow velocity on the shipped lattice (0.547 spacings a cell), splatted to
the grid normalised (sum w u / sum w, the walls as mirror images) and interpolated back bilinearly
over the cells holding liquid, as the particle pass does. Prints the share of the mode kept
(<u', u> / <u, u>) for the chapter's radial kernel, for a bilinear hat (a narrower velocity
kernel) and for the affine transfer (APIC: each particle deposits u_p + C_p (x_i - x_p), C_p its
velocity gradient). The PIC share of every step removes (1 - kept) of the mode that many times.
docs/physics.md, "Where sloshing loses its energy".
Usage: transfer_loss.py [CELLS_ALONG_L ...]   (needs numpy: python3-numpy)"""
import sys

import numpy as np

L, H = 0.5, 0.1          # tank length and still depth, m
SPACINGS_PER_CELL = 0.547  # rest_pool_2d's particle spacing over its cell
K = np.pi / L


def lattice(h):
    s = h * SPACINGS_PER_CELL
    xs = (np.arange(int(L / s)) + 0.5) * s
    ys = (np.arange(int(H / s)) + 0.5) * s
    x, y = np.meshgrid(xs, ys, indexing="ij")
    return x.ravel(), y.ravel()


def mode(x, y):
    """Velocity of phi = cos(k x) cosh(k y) (floor at y = 0) and its gradient."""
    u, v = np.sin(K * x) * np.cosh(K * y), -np.cos(K * x) * np.sinh(K * y)
    ux, uy = K * np.cos(K * x) * np.cosh(K * y), K * np.sin(K * x) * np.sinh(K * y)
    return u, v, (ux, uy, uy, -ux)  # (du/dx, du/dy, dv/dx, dv/dy)


def images(x, y, u, v, grad):
    """The particles and their mirror images across the walls x = 0, x = L and the floor."""
    ux, uy, vx, vy = grad
    yield x, y, u, v, (ux, uy, vx, vy)
    yield -x, y, -u, v, (ux, -uy, -vx, vy)
    yield 2 * L - x, y, -u, v, (ux, -uy, -vx, vy)
    yield x, -y, u, -v, (ux, -uy, -vx, vy)


def splat(cells, h, kernel, affine):
    x, y = lattice(h)
    u, v, grad = mode(x, y)
    ny = int(3 * H / h)
    centres_x, centres_y = (np.arange(cells) + 0.5) * h, (np.arange(ny) + 0.5) * h
    w_sum, wu, wv = (np.zeros((cells, ny)) for _ in range(3))
    for px, py, pu, pv, (ux, uy, vx, vy) in images(x, y, u, v, grad):
        for i in range(cells):
            near = np.abs(centres_x[i] - px) < 3.0 * h
            for j in range(ny):
                dx, dy = centres_x[i] - px[near], centres_y[j] - py[near]
                w = kernel(dx / h, dy / h)
                du = ux[near] * dx + uy[near] * dy if affine else 0.0
                dv = vx[near] * dx + vy[near] * dy if affine else 0.0
                w_sum[i, j] += w.sum()
                wu[i, j] += (w * (pu[near] + du)).sum()
                wv[i, j] += (w * (pv[near] + dv)).sum()
    fluid = w_sum > 1e-6
    safe = np.maximum(w_sum, 1e-12)
    return np.where(fluid, wu / safe, 0.0), np.where(fluid, wv / safe, 0.0), fluid


def interpolate(grid, fluid, x, y, h):
    gx, gy = x / h - 0.5, y / h - 0.5
    bx, by = np.floor(gx).astype(int), np.floor(gy).astype(int)
    fx, fy = gx - bx, gy - by
    total, value = np.zeros_like(x), np.zeros_like(x)
    for ox in (0, 1):
        for oy in (0, 1):
            ix = np.clip(bx + ox, 0, grid.shape[0] - 1)
            iy = np.clip(by + oy, 0, grid.shape[1] - 1)
            w = (fx if ox else 1 - fx) * (fy if oy else 1 - fy) * fluid[ix, iy]
            total += w
            value += w * grid[ix, iy]
    return value / np.maximum(total, 1e-12)


def kept(cells, kernel, affine=False):
    h = L / cells
    x, y = lattice(h)
    u, v, _ = mode(x, y)
    gu, gv, fluid = splat(cells, h, kernel, affine)
    u2, v2 = interpolate(gu, fluid, x, y, h), interpolate(gv, fluid, x, y, h)
    return float((u2 * u + v2 * v).sum() / (u * u + v * v).sum())


def radial(r):
    return lambda dx, dy: np.maximum(1.0 - (dx * dx + dy * dy) / (r * r), 0.0) ** 3


def hat(dx, dy):
    return np.maximum(1.0 - np.abs(dx), 0.0) * np.maximum(1.0 - np.abs(dy), 0.0)


for cells in [int(a) for a in sys.argv[1:]] or [64, 128]:
    print(f"{cells} cells along L: mode kept per transfer: radial r = 3: {kept(cells, radial(3.0)):.6f}, "
          f"r = 1.5: {kept(cells, radial(1.5)):.6f}, bilinear hat: {kept(cells, hat):.6f}, "
          f"affine (APIC), r = 3: {kept(cells, radial(3.0), True):.6f}")
