/* indirect_reference.cl -- the converged reference of the indirect scene
 * (docs/design.md section 9): one-bounce indirect irradiance on the floor,
 *   E_ind(x) = (rho / pi) int_walls+ceiling E_dir(y) cos_x cos_y / r^2 dA(y),
 * in three passes (host/methods/family_indirect.cpp runs them):
 *   edir_nodes  E_dir at the 4 x 4 Gauss nodes of every cell of every surface
 *               (common/indirect.h's node grid) and at every cell's centre, by
 *               the floor reference's adaptive area cubature (common/area_ref.h)
 *               with the surface's normal as the receiver normal;
 *   edir_delta  per surface, the largest deviation of the cells' bicubic
 *               interpolants from E_dir at the centres: the interpolation error;
 *   render      per floor pixel, the globally adaptive bounce cubature
 *               (lb_bounce_irradiance) with its error estimate plus the
 *               interpolation's (lb_bounce_interp_err).
 * The room is convex and empty: no visibility anywhere (common/indirect.h).
 * @variants: ""
 */
#include "common/lbmath.h"
#include "common/area_ref.h"
#include "common/indirect.h"
#include "common/entry.h"

/* Node i (0 .. nodes-1) of the grid, or cell centre i - nodes: its surface
 * point and normal. grid as in common/indirect.h; cells[k] the first cell
 * index of surface k in the centre list (cells[5] = their count). */
LB_FN void ind_node_point(__global const int* grid, __global const int* cells, int nodes, int i, real3* p, real3* n)
{
    real3 o, a, b;
    int k = 0;
    real s, t;
    if (i < nodes) {
        while (k + 1 < LB_ROOM_NSURF && i >= grid[3 * (k + 1) + 2])
            ++k;
        int gs = grid[3 * k], j = i - grid[3 * k + 2];
        int is = j % (4 * gs), it = j / (4 * gs);
        s = ((real)(is / 4) + lb_gl4_x(is % 4)) / (real)gs;
        t = ((real)(it / 4) + lb_gl4_x(it % 4)) / (real)grid[3 * k + 1];
    } else {
        int c = i - nodes;
        while (k + 1 < LB_ROOM_NSURF && c >= cells[k + 1])
            ++k;
        int gs = grid[3 * k], j = c - cells[k];
        s = ((real)(j % gs) + R(0.5)) / (real)gs;
        t = ((real)(j / gs) + R(0.5)) / (real)grid[3 * k + 1];
    }
    lb_room_surface(k, &o, &a, &b, n);
    *p = o + a * s + b * t;
}

/* E_dir (lux) at every node and cell centre (nodes + cells[5] work-items).
 * visibility: the light is inside the convex room; nothing shades a wall. */
__kernel void edir_nodes(__global const real* P, __global const float* lum, __global const int* grid,
                         __global const int* cells, int nodes, __global real* edir, __global real* centre,
                         __global real* edir_err, real rel_tol, int max_splits)
{
    int i = get_global_id(0);
    if (i >= nodes + cells[LB_ROOM_NSURF])
        return;
    real3 p, n;
    ind_node_point(grid, cells, nodes, i, &p, &n);
    real err;
    int splits;
    real e = lb_ref_irradiance(lum, lb_scene_light(P), p, n, rel_tol, max_splits, &err, &splits);
    if (i < nodes) {
        edir[i] = e;
        edir_err[i] = err;
    } else {
        centre[i - nodes] = e;
    }
}

/* delta[k] = max over the cells of surface k of |E_dir(centre) -
 * interpolant(centre)| plus the largest node error estimate (one work-item per
 * surface). */
__kernel void edir_delta(__global const int* grid, __global const int* cells, __global const real* edir,
                         __global const real* centre, __global const real* edir_err, __global real* delta)
{
    int k = get_global_id(0);
    if (k >= LB_ROOM_NSURF)
        return;
    int gs = grid[3 * k], gt = grid[3 * k + 1];
    real d = R(0);
    for (int j = 0; j < gt; ++j)
        for (int i = 0; i < gs; ++i) {
            real s = ((real)i + R(0.5)) / (real)gs, t = ((real)j + R(0.5)) / (real)gt;
            real v = lb_edir_interp(edir, grid, k, s, t);
            d = fmax(d, fabs(v - centre[cells[k] + j * gs + i]));
        }
    real en = R(0);
    for (int i = grid[3 * k + 2]; i < grid[3 * k + 2] + 16 * gs * gt; ++i)
        en = fmax(en, edir_err[i]);
    delta[k] = d + en;
}

/* One floor pixel per work-item: E_ind and its error estimate, the bounce
 * cubature's plus the interpolation's. */
#define LB_ENTRY_ARGS                                                                                          \
    , __global const real *edir, __global const int *grid, __global const real *delta LB_REFERENCE_ARGS
LB_RENDER_KERNEL
{
    LB_REFERENCE_OPENING;
    real rho = P[LB_P_ALBEDO];
    lb_adapt_report rep;
    real e = lb_bounce_irradiance(edir, grid, x, nx, rho, lb_adapt_goal_of(rel_tol, max_splits), &rep);
    splits = rep.splits;
    LB_REFERENCE_STORE(e, rep.err + lb_bounce_interp_err(delta, x, nx, rho));
}
