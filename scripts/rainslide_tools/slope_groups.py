"""Sliding groups of a slope run: points linked by chains of close neighbours,
and the initial surface profile (the toe of the cut)."""
import numpy as np


def _neighbour_pairs(xy, link):
    """Index pairs (i < j or across cells) of points closer than `link` (grid hash)."""
    n = len(xy)
    if n < 2:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    cell = np.floor((xy - xy.min(axis=0)) / link).astype(np.int64) + 1
    ny = int(cell[:, 1].max()) + 3
    key = cell[:, 0] * ny + cell[:, 1]
    order = np.argsort(key, kind="stable")
    sorted_key = key[order]
    pi, pj = [], []
    # Half of the 3x3 neighbourhood: each pair of cells is visited once.
    for dx, dy in ((0, 0), (1, -1), (1, 0), (1, 1), (0, 1)):
        nkey = key + dx * ny + dy
        start = np.searchsorted(sorted_key, nkey, "left")
        count = np.searchsorted(sorted_key, nkey, "right") - start
        total = int(count.sum())
        if total == 0:
            continue
        i = np.repeat(np.arange(n), count)
        offset = np.arange(total) - np.repeat(np.cumsum(count) - count, count)
        j = order[np.repeat(start, count) + offset]
        keep = np.sum((xy[i] - xy[j]) ** 2, axis=1) <= link * link
        if dx == 0 and dy == 0:
            keep &= i < j
        pi.append(i[keep])
        pj.append(j[keep])
    return np.concatenate(pi), np.concatenate(pj)


def connected_groups(xy, link):
    """Labels 0..G-1 of the groups of points linked by chains closer than `link`."""
    xy = np.asarray(xy, dtype=float).reshape(-1, 2)
    n = len(xy)
    if n == 0:
        return np.zeros(0, dtype=np.int64)
    i, j = _neighbour_pairs(xy, link)
    label = np.arange(n)
    # Hook roots to the smallest neighbouring label, then jump pointers.
    while i.size:
        li, lj = label[i], label[j]
        differ = li != lj
        if not differ.any():
            break
        li, lj = li[differ], lj[differ]
        low = np.minimum(li, lj)
        np.minimum.at(label, li, low)
        np.minimum.at(label, lj, low)
        while True:
            jumped = label[label]
            if np.array_equal(jumped, label):
                break
            label = jumped
    return np.unique(label, return_inverse=True)[1].astype(np.int64)


def sliding_groups(xy, area, candidate, link, min_area):
    """Groups of candidate points: (group label per point or -1, counted labels, areas)."""
    idx = np.flatnonzero(candidate)
    labels = np.full(len(xy), -1, dtype=np.int64)
    if idx.size == 0:
        return labels, np.zeros(0, dtype=np.int64), np.zeros(0)
    lab = connected_groups(xy[idx], link)
    g_area = np.bincount(lab, weights=area[idx])
    counted = np.flatnonzero(g_area >= min_area)
    keep = np.isin(lab, counted)
    labels[idx[keep]] = lab[keep]
    return labels, counted, g_area[counted]


#---------------------------------------------------------------------------#
def surface_profile(x0, spacing):
    """Top of the initial soil per column of points: (column x, top y = highest
    point + spacing / 2). Points generated in vertical columns (the usual case)
    give one column per distinct x; otherwise columns of width `spacing`."""
    key = np.round(x0[:, 0] / (1e-3 * spacing)).astype(np.int64)
    uniq, col = np.unique(key, return_inverse=True)
    if uniq.size > 0.5 * len(x0):  # not in columns: bin them
        origin = x0[:, 0].min() - 0.5 * spacing
        col = np.floor((x0[:, 0] - origin) / spacing).astype(np.int64)
    ncol = col.max() + 1
    top = np.full(ncol, -np.inf)
    np.maximum.at(top, col, x0[:, 1])
    xc = np.bincount(col, weights=x0[:, 0], minlength=ncol)
    cnt = np.bincount(col, minlength=ncol)
    ok = cnt > 0
    return xc[ok] / cnt[ok], top[ok] + 0.5 * spacing


def derive_toe_x(x0, spacing):
    """x of the lower-right corner of the sloping surface: where the initial surface
    profile reaches the flat floor at its right end (midway between the last column
    above the floor and the first column on it; within a point spacing)."""
    xc, top = surface_profile(x0, spacing)
    floor = top[-1]
    k = len(top) - 1
    while k > 0 and top[k - 1] <= floor + 0.5 * spacing:
        k -= 1
    return float(0.5 * (xc[k - 1] + xc[k])) if k > 0 else float(xc[0])
