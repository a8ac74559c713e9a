/* polygon.h -- convex polygons in 3D: clipping, closest point, dynamic points.
 * Compiles as OpenCL C and C++ (see vec.h). Polygons are arrays of at most
 * LB_MAXV vertices in either winding. */

/* Sutherland-Hodgman clip of the convex polygon p[0..n) to the half-space
 * dot(nrm, x) >= d, in place; returns the new vertex count (0 when nothing is
 * left). A vertex exactly on the plane is kept once: intersections are only
 * made on edges whose ends lie strictly on opposite sides. */
LB_FN int lb_clip_polygon(real3* p, int n, real3 nrm, real d)
{
    real3 q[LB_MAXV];
    int m = 0;
    for (int i = 0; i < n; ++i) {
        real3 a = p[i];
        real3 b = p[(i + 1 == n) ? 0 : i + 1];
        real da = dot(nrm, a) - d;
        real db = dot(nrm, b) - d;
        if (da >= R(0) && m < LB_MAXV)
            q[m++] = a;
        if (((da > R(0) && db < R(0)) || (da < R(0) && db > R(0))) && m < LB_MAXV)
            q[m++] = a + (b - a) * (da / (da - db));
    }
    for (int i = 0; i < m; ++i)
        p[i] = q[i];
    return m;
}

/* Vector area (Newell) of the polygon: normal times area, following the winding. */
LB_FN real3 lb_polygon_vector_area(const real3* p, int n)
{
    real3 s = R3(0, 0, 0);
    for (int i = 0; i < n; ++i)
        s += cross(p[i], p[(i + 1 == n) ? 0 : i + 1]);
    return R(0.5) * s;
}

/* Parameter t in [0, 1] of the point of segment [a, b] closest to q. */
LB_FN real lb_segment_param(real3 a, real3 b, real3 q)
{
    real3 e = b - a;
    real ee = dot(e, e);
    return ee > R(0) ? clamp(dot(q - a, e) / ee, R(0), R(1)) : R(0);
}

/* Closest point of segment [a, b] to q; exactly a or b when clamped there. */
LB_FN real3 lb_closest_on_segment(real3 a, real3 b, real3 q)
{
    real t = lb_segment_param(a, b, q);
    return t <= R(0) ? a : (t >= R(1) ? b : a + (b - a) * t);
}

/* Closest point to q over the edges of the polygon p[0..n), by comparing
 * squared distances: the fallback of lb_closest_point_polygon for degenerate
 * polygons. *where: 1 on an edge, 2 at a vertex. */
LB_FN real3 lb_closest_point_edges(const real3* p, int n, real3 qp, int* where)
{
    real best = R(-1);
    real3 bp = p[0];
    int at_vertex = 1;
    for (int i = 0; i < n; ++i) {
        real3 a = p[i];
        real3 b = p[(i + 1 == n) ? 0 : i + 1];
        real t = lb_segment_param(a, b, qp);
        real3 c = t <= R(0) ? a : (t >= R(1) ? b : a + (b - a) * t);
        real3 dc = c - qp;
        real dd = dot(dc, dc);
        if (best < R(0) || dd < best) {
            best = dd;
            bp = c;
            at_vertex = (t <= R(0) || t >= R(1)) ? 1 : 0;
        }
    }
    *where = at_vertex ? 2 : 1;
    return bp;
}

/* Closest point to q on the convex planar polygon p[0..n) (n >= 1) with plane
 * normal nrm: the one implementation behind the closest point (CP) and the
 * clamping of NP and MRP (dynamic.h), used by the cp/np/mrp baselines, the
 * cubature and the Voronoi method. q is projected into the plane. *where
 * receives 0 inside, 1 on an edge, 2 at a vertex (the three cases of paper
 * Fig. 5).
 * The case is decided by tests linear in q -- the signed distance of q from
 * each edge's line and its projection parameter on the edge -- not by
 * comparing squared distances: those cannot tell an edge point from a vertex
 * nearer than |q| sqrt(ulp) (7e-4 at 2 m in float; 0.24 for the far target of
 * a grazing NP at 1e3 m), which made CP hop onto corners and NP hop between
 * them. Linear tests err by ~|q| ulp. q outside edge i with its projection
 * inside the edge -> that projection (a convex polygon lies behind the edge's
 * line, so nothing is nearer; of several such edges the one q is farthest
 * outside); else the vertex whose normal cone holds q. */
LB_FN real3 lb_closest_point_polygon(const real3* p, int n, real3 nrm, real3 q, int* where)
{
    real3 qp = q - nrm * dot(q - p[0], nrm);
    real wind = n >= 3 ? dot(lb_polygon_vector_area(p, n), nrm) : R(0);
    if (wind == R(0))
        return lb_closest_point_edges(p, n, qp, where);
    real sg = wind > R(0) ? R(1) : R(-1);
    real worst = R(0);
    int edge = -1, inside = 1;
    real edge_s = R(0);
    real sps[LB_MAXV];
    for (int i = 0; i < n; ++i) {
        real3 a = p[i];
        real3 e = p[(i + 1 == n) ? 0 : i + 1] - a;
        real ee = dot(e, e);
        sps[i] = ee > R(0) ? dot(qp - a, e) / ee : R(0);
        real side = ee > R(0) ? sg * dot(cross(e, qp - a), nrm) / sqrt(ee) : R(0); /* < 0: outside edge i */
        if (side < R(0))
            inside = 0;
        if (side < R(0) && sps[i] >= R(0) && sps[i] <= R(1) && side < worst) {
            worst = side;
            edge = i;
            edge_s = sps[i];
        }
    }
    if (inside) {
        *where = 0;
        return qp;
    }
    if (edge >= 0) {
        *where = 1;
        return p[edge] + (p[(edge + 1 == n) ? 0 : edge + 1] - p[edge]) * edge_s;
    }
    /* vertex k: beyond the end of edge k-1 and before the start of edge k */
    for (int k = 0; k < n; ++k)
        if (sps[(k + n - 1) % n] >= R(1) && sps[k] <= R(0)) {
            *where = 2;
            return p[k];
        }
    return lb_closest_point_edges(p, n, qp, where);
}
