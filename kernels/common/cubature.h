/* cubature.h -- scattered-sampling cubature of a photometric polygonal light
 * (paper Sec. 5, thesis 5.2), the geometry and the weights. Compiles as OpenCL
 * C and C++ (see vec.h).
 *
 * The procedure for one shading point x with normal nx:
 *   1. plane_eps (paper 5.3): if x is closer than plane_eps to the light's
 *      plane, move it along n_L to distance plane_eps on its own side (a point
 *      exactly in the plane goes to the front). The paper's opposite shift of
 *      the lookup directions is skipped, as in the paper's final version.
 *   2. Clip the light at the horizon, tilted by horizon_eps (thesis 5.2.4):
 *      the thesis raises the horizontal plane by eps, intersects it with the
 *      light's plane and clips with the plane through x and that line. Inside
 *      the light's plane that clip is exactly the half-plane nx . (p - x) >=
 *      eps, which is what we clip with (eps = 0: the plain horizon).
 *   3. Dynamic points on the clipped polygon (flags LB_CUB_*): closest point,
 *      normal point, most representative point (paper 4.2, each clamped to the
 *      polygon), area barycentre.
 *   4. Triangulate in the light's plane coordinates q = (p . u, p . v) (p =
 *      position relative to x): a fan around the first dynamic point (paper
 *      5.2; a fan from a corner when there is none), the further dynamic
 *      points inserted robustly (thesis 5.2.2 gave up on this; see
 *      lb_cub_insert), then for "delaunay" Lawson edge flips until the
 *      spherical empty-circumcircle test (thesis Eq. 5.8) holds for every
 *      interior edge (see lb_cub_incircle). With more than one dynamic point
 *      use delaunay: the fan's result depends on which fan triangle a further
 *      point falls into, and jumps (up to 20% E measured) when it crosses a
 *      fan edge; Delaunay jumps only at cocircular events (<= 2e-4 E measured).
 *   5. Per-sample weights w_i, so that E = sum_i w_i L_i with L_i = I(d_i) /
 *      (A |n_L . d_i|) (paper Eq. 2). Every weighting is linear in the L_i:
 *        sample  (paper Eq. 9):  E = sum_tri |D| (L_i G_i + L_j G_j + L_k G_k) / 3
 *        average (paper Eq. 10): E = sum_tri |D| (L_i + L_j + L_k)/3 (G_i + G_j + G_k)/3
 *        dotout:                 E = sum_tri |D| (c_i L_i + c_j L_j + c_k L_k)/(c_i + c_j + c_k) (G_i + G_j + G_k)/3
 *      with G = max(0, nx . w) and c = |n_L . w| (w the unit direction from x
 *      to the sample). dotout is Eq. 10 with the vertex radiances weighted by
 *      |n_L . w| (docs/design.md section 4): the triangle's radiance is the mean intensity
 *      over the mean projected area, (I_i + I_j + I_k) / (A (c_i + c_j + c_k)),
 *      so a vertex seen at a grazing angle, whose L = I / (A c) is least
 *      certain, counts least; for a Lambertian emitter it equals average.
 *      |D| is the spherical excess by Van Oosterom-Strackee (atan2 form,
 *      lb_tri_solid_angle), 0 in the limit of a degenerate triangle.
 *   6. normalize=formfactor (thesis Eq. 5.11): E = E_lambert * (sum w_i L_i) /
 *      (sum w_i), E_lambert the exact irradiance of the clipped polygon at unit
 *      radiance (Baum et al., lb_polygon_irradiance_lambert). sum w_i is the
 *      same cubature applied to L = 1, i.e. the cubature's estimate of
 *      integral G dw, so the ratio is the cosine-weighted mean radiance of
 *      Eq. 5.11; for a Lambertian emitter (L constant) the result is exact.
 */

/* Static samples (the cubature's `static` parameter, 0 .. 4): structural, so
 * that the triangulation is sized for them only where they are used. */
#ifndef LB_CUB_STATIC
#define LB_CUB_STATIC 0
#endif
#define LB_CUB_MAXS (12 + LB_CUB_STATIC) /* samples: LB_MAXV polygon vertices + 4 dynamic points + static */
#define LB_CUB_MAXT (20 + 2 * LB_CUB_STATIC) /* triangles: at most 2 S - h - 2 <= 2 * 12 - 3 - 2 = 19, + 2 per static */
#define LB_CUB_MAXFLIPS 64 /* Lawson flips always end (each flip lowers a lifted volume); a guard anyway */

/* Dynamic point flags (the `dynamic` option, a bit set). The first present in
 * this order is the fan centre: CP (as the paper), then MRP, NP, barycentre. */
#define LB_CUB_CP 1
#define LB_CUB_NP 2
#define LB_CUB_MRP 4
#define LB_CUB_BARY 8

#define LB_CUB_FAN 0
#define LB_CUB_DELAUNAY 1

#define LB_CUB_SAMPLE 0
#define LB_CUB_AVERAGE 1
#define LB_CUB_DOTOUT 2

/* The cubature's structural choices, one value for all of them (a kernel
 * fills it from its -D flags, the same for every work-item; the host's unit
 * tests from their loops). */
typedef struct {
    int triangulation; /* LB_CUB_FAN | LB_CUB_DELAUNAY */
    int weighting;     /* LB_CUB_SAMPLE | LB_CUB_AVERAGE | LB_CUB_DOTOUT */
    int formfactor;    /* normalize: 0 none, 1 formfactor (thesis Eq. 5.11; step 6 above) */
    int dynamic;       /* bit set of LB_CUB_CP, _NP, _MRP, _BARY; 0 = the corners only */
    int nstatic;       /* static samples 0 .. LB_CUB_STATIC at (s_k, t_k) of lb_cub_tunables */
} lb_cub_options;

/* The paper's method: a fan around CP, average weights (Eq. 10), no
 * normalization. */
LB_FN lb_cub_options lb_cub_paper_options(void)
{
    lb_cub_options o;
    o.triangulation = LB_CUB_FAN;
    o.weighting = LB_CUB_AVERAGE;
    o.formfactor = 0;
    o.dynamic = LB_CUB_CP;
    o.nstatic = 0;
    return o;
}

/* The cubature's continuous tunables, declared once: the fields of
 * lb_cub_tunables, the real-valued arguments of kernels/cubature.cl's kernel
 * (in this order, after want_stats) and the values the host binds to them
 * (host/methods/family_cubature.cpp; each is a parameter of the method).
 *   plane_eps    (m) receivers nearer the light's plane move to this distance (step 1)
 *   horizon_eps  (m) the tilted horizon (step 2)
 *   corner_inset the corner samples' lookup moved towards the corner mean
 *                (lb_cubature_irradiance; 0 = plain)
 *   dyn_weight   scale of the dynamic samples' weights (1 = plain)
 *   blend_dist   (m) the far-field blend into the 3 x 3 grid MC (lb_blend_weight)
 *   area_q, area_sin  the area form's blend (cubature/clip_blend.inc lb_area_weight)
 *   s1, t1 .. s4, t4  the static samples' positions in the light's unit square
 *                (s along u, t along v; the first opt.nstatic are used) */
#define LB_CUB_TUNABLES(X)                                                                                           \
    X(plane_eps) X(horizon_eps) X(corner_inset) X(dyn_weight) X(blend_dist) X(area_q) X(area_sin) X(s1) X(t1) X(s2) \
        X(t2) X(s3) X(t3) X(s4) X(t4)
#define LB_CUB_TUNABLE_FIELD(name) real name;
typedef struct {
    LB_CUB_TUNABLES(LB_CUB_TUNABLE_FIELD)
} lb_cub_tunables;
#undef LB_CUB_TUNABLE_FIELD

/* The plain method at these two tolerances: no inset, the dynamic samples at
 * their triangulation weight, no far-field or area blend. */
LB_FN lb_cub_tunables lb_cub_plain_tunables(real plane_eps, real horizon_eps)
{
    lb_cub_tunables t;
    t.plane_eps = plane_eps;
    t.horizon_eps = horizon_eps;
    t.corner_inset = R(0);
    t.dyn_weight = R(1);
    t.blend_dist = R(1e30); /* beyond every scene */
    t.area_q = R(1e30);     /* the area rule nowhere by distance */
    t.area_sin = R(0);      /* nor by elevation */
    t.s1 = t.t1 = t.s2 = t.t2 = t.s3 = t.t3 = t.s4 = t.t4 = R(0.5); /* unused: no static samples */
    return t;
}

/* Merge tolerance, relative to the clipped light's size: samples closer than
 * tol * size are one sample, a sample closer than that to an edge lies on the
 * edge. Float positions relative to x carry ~1e-7 relative error, so 1e-5
 * leaves two orders of margin; the snap moves a sample by at most tol * size,
 * which bounds the jump it can cause. */
LB_FN real lb_cub_tol(void)
{
#if LB_REAL_IS_DOUBLE
    return R(1e-9);
#else
    return R(1e-5);
#endif
}

/* In-circle tolerance: 32 ulp of the dimensionless determinant (its
 * rounding error is a few ulp). Not the merge tolerance: a sample just
 * outside the merge distance eps of another makes determinants of order eps,
 * and those must still be decided, or the flips near a cluster of samples
 * would stop early and leave a triangulation different from the one the
 * cluster collapses to when its samples merge. */
LB_FN real lb_cub_incircle_tol(void)
{
#if LB_REAL_IS_DOUBLE
    return R(32) * R(2.220446049250313e-16);
#else
    return R(32) * R(1.1920929e-7);
#endif
}

/* The triangulation of one shading point: a compact, fixed-capacity structure
 * in the spirit of thesis 5.2.1. Triangles are index triples, counter-clockwise
 * in q; neighbours are found by searching the few triangles for the reversed
 * edge instead of storing edge arrays (at most 19 triangles, usually 2 to 6:
 * cheaper to scan than to keep the thesis' EV/EM arrays consistent through
 * splits and flips). Private memory: ~450 bytes in float. */
typedef struct {
    real3 p[LB_CUB_MAXS]; /* sample positions relative to x (on the light's plane) */
    real2 q[LB_CUB_MAXS]; /* the same in the light's plane: (p . u, p . v), origin = x's projection */
    real r[LB_CUB_MAXS];  /* |p|: the lifting of the spherical in-circle test */
    char t[3 * LB_CUB_MAXT];
    int ns, nh, nt;       /* samples, hull (polygon) samples, triangles */
    int flips;            /* edge flips done (statistics) */
    real eps;             /* merge tolerance, a length in q */
} lb_cub;

LB_FN real lb_cross2(real2 a, real2 b)
{
    return a.x * b.y - a.y * b.x;
}

/* Signed distance of c from the line a -> b, positive on its left. */
LB_FN real lb_cub_side(real2 a, real2 b, real2 c)
{
    real2 e = b - a;
    real l = length(e);
    return l > R(0) ? lb_cross2(e, c - a) / l : R(0);
}

LB_FN int lb_cub_add(lb_cub* T, real3 p, real3 u, real3 v)
{
    int i = T->ns++;
    T->p[i] = p;
    T->q[i] = R2(dot(p, u), dot(p, v));
    T->r[i] = length(p);
    return i;
}

LB_FN void lb_cub_set(lb_cub* T, int k, int a, int b, int c)
{
    T->t[3 * k] = (char)a;
    T->t[3 * k + 1] = (char)b;
    T->t[3 * k + 2] = (char)c;
}

LB_FN int lb_cub_tv(const lb_cub* T, int k, int i)
{
    return (int)T->t[3 * k + i];
}

/* Spherical empty-circumcircle test (thesis Eq. 5.8, Renka 1997) for the
 * counter-clockwise triangle (a, b, c) and the point d: > 0 when d lies inside
 * the circumcircle of the spherical triangle seen from x.
 * On unit vectors the test is the sign of det[w_i, 1] (4x4, i = a, b, c, d).
 * Scaling row i by r_i = |p_i| gives det[p_i, r_i], and as the p_i lie in one
 * plane, p_i = o + q_i.x u + q_i.y v, this is det(u, v, o) det[q_i, 1, r_i]: the
 * planar in-circle test with the lifting q -> r(q) = sqrt(h^2 + |q|^2) instead
 * of the paraboloid. We evaluate that 3x3 determinant of differences, with
 * r_i - r_d = (q_i - q_d) . (q_i + q_d) / (r_i + r_d) free of cancellation: it
 * stays accurate in float when x is far away (where the unit-vector form of
 * Eq. 5.8 loses all digits) and when x approaches the light's plane. The
 * result is made dimensionless by the quadrilateral's size. */
LB_FN real lb_cub_incircle(const lb_cub* T, int a, int b, int c, int d)
{
    real2 qd = T->q[d];
    real2 qa = T->q[a] - qd, qb = T->q[b] - qd, qc = T->q[c] - qd;
    real la = dot(qa, T->q[a] + qd) / (T->r[a] + T->r[d]);
    real lbb = dot(qb, T->q[b] + qd) / (T->r[b] + T->r[d]);
    real lc = dot(qc, T->q[c] + qd) / (T->r[c] + T->r[d]);
    real det = la * lb_cross2(qb, qc) + lbb * lb_cross2(qc, qa) + lc * lb_cross2(qa, qb);
    /* scale: the cube of the largest distance among the four points, the
     * same from both triangles of the edge (a per-side scale would let a
     * thin triangle pass the tolerance from one side and fail it from the
     * other) */
    real m = fmax(fmax(length(qa), length(qb)), length(qc));
    m = fmax(m, fmax(length(T->q[a] - T->q[b]), fmax(length(T->q[b] - T->q[c]), length(T->q[c] - T->q[a]))));
    real s = m * m * m;
    return s > R(0) ? det / s : R(0);
}

/* The triangle holding the directed edge a -> b, its local edge index in *e;
 * -1 when the edge is on the hull. */
LB_FN int lb_cub_find_edge(const lb_cub* T, int a, int b, int* e)
{
    for (int k = 0; k < T->nt; ++k)
        for (int i = 0; i < 3; ++i)
            if (lb_cub_tv(T, k, i) == a && lb_cub_tv(T, k, (i + 1) % 3) == b) {
                *e = i;
                return k;
            }
    return -1;
}

/* Start from the clipped convex polygon poly[0..n) (relative to x): its
 * vertices in counter-clockwise order in q, consecutive duplicates (closer
 * than eps) merged and vertices within eps of the line through their
 * neighbours dropped (the clip can make both near a corner); the area changes
 * by at most eps times the perimeter. Returns the hull size (< 3: nothing). */
LB_FN int lb_cub_init(lb_cub* T, const real3* poly, int n, real3 u, real3 v)
{
    T->ns = 0;
    T->nt = 0;
    T->nh = 0;
    T->flips = 0;
    T->eps = R(0);
    if (n < 3)
        return 0;
    /* winding and size in q */
    real2 q0 = R2(dot(poly[0], u), dot(poly[0], v));
    real area = R(0), size = R(0), mag = R(0);
    for (int i = 0; i < n; ++i) {
        real2 a = R2(dot(poly[i], u), dot(poly[i], v)) - q0;
        real2 b = R2(dot(poly[(i + 1) % n], u), dot(poly[(i + 1) % n], v)) - q0;
        area += lb_cross2(a, b);
        size = fmax(size, length(a));
        mag = fmax(mag, fmax(fabs(a.x + q0.x), fabs(a.y + q0.y)));
    }
    T->eps = lb_cub_tol() * size + R(16) * lb_real_eps() * mag;
    for (int k = 0; k < n; ++k) {
        real3 p = poly[area >= R(0) ? k : n - 1 - k];
        real2 q = R2(dot(p, u), dot(p, v));
        if (T->ns > 0 && length(q - T->q[T->ns - 1]) <= T->eps)
            continue;
        lb_cub_add(T, p, u, v);
    }
    if (T->ns > 1 && length(T->q[T->ns - 1] - T->q[0]) <= T->eps)
        T->ns--;
    /* drop (nearly) collinear vertices, repeatedly */
    for (int changed = 1; changed && T->ns >= 3;) {
        changed = 0;
        for (int i = 0; i < T->ns && T->ns >= 3; ++i) {
            int a = (i + T->ns - 1) % T->ns, b = (i + 1) % T->ns;
            if (lb_cub_side(T->q[b], T->q[a], T->q[i]) <= T->eps) { /* i right of prev -> next: convex */
                for (int j = i; j + 1 < T->ns; ++j) {
                    T->p[j] = T->p[j + 1];
                    T->q[j] = T->q[j + 1];
                    T->r[j] = T->r[j + 1];
                }
                T->ns--;
                changed = 1;
                break;
            }
        }
    }
    if (T->ns < 3)
        T->ns = 0;
    T->nh = T->ns;
    return T->ns;
}

/* Fan of the hull from sample k (a hull vertex): triangles (k, i, i+1). */
LB_FN void lb_cub_fan_vertex(lb_cub* T, int k)
{
    int h = T->nh;
    T->nt = 0;
    for (int j = 1; j + 1 < h; ++j)
        lb_cub_set(T, T->nt++, k, (k + j) % h, (k + j + 1) % h);
}

/* Split the edge a -> b (local edge e of triangle k) at the new sample s, and
 * the triangle across it if there is one. */
LB_FN void lb_cub_split_edge(lb_cub* T, int k, int e, int s)
{
    int a = lb_cub_tv(T, k, e), b = lb_cub_tv(T, k, (e + 1) % 3), c = lb_cub_tv(T, k, (e + 2) % 3);
    int e2;
    int k2 = lb_cub_find_edge(T, b, a, &e2);
    lb_cub_set(T, k, a, s, c);
    lb_cub_set(T, T->nt++, s, b, c);
    if (k2 >= 0) {
        int d = lb_cub_tv(T, k2, (e2 + 2) % 3);
        lb_cub_set(T, k2, b, s, d);
        lb_cub_set(T, T->nt++, s, a, d);
    }
}

/* Robust insertion of the point p (relative to x, on the light's plane, inside
 * the hull up to the tolerance) into the triangulation. Returns its sample
 * index, an existing one when it coincides with a sample, -1 when it lies
 * outside the hull (it cannot for points clamped to the polygon) or there is
 * no room.
 *   coincident: within eps of a sample -> that sample;
 *   locate: the triangle whose smallest signed edge distance is largest (the
 *     one p is deepest in: the choice is unambiguous even where the eps-bands
 *     of neighbouring triangles overlap);
 *   on an edge: that smallest distance <= eps -> p is projected onto the edge
 *     (moved by <= eps) and the edge split, with the triangle across it;
 *   inside: the triangle is split in three.
 * Every new triangle has positive orientation up to rounding: the projection
 * puts p strictly between the edge's ends (they are > eps away), and an
 * interior p is > eps from every edge. */
LB_FN int lb_cub_insert(lb_cub* T, real3 p, real3 u, real3 v)
{
    if (T->nt == 0)
        return -1;
    real2 q = R2(dot(p, u), dot(p, v));
    for (int i = 0; i < T->ns; ++i)
        if (length(q - T->q[i]) <= T->eps)
            return i;
    if (T->ns >= LB_CUB_MAXS || T->nt + 2 > LB_CUB_MAXT)
        return -1;
    int best = -1, bedge = 0;
    real bd = R(0);
    for (int k = 0; k < T->nt; ++k) {
        real dmin = R(0);
        int emin = 0;
        for (int i = 0; i < 3; ++i) {
            real d = lb_cub_side(T->q[lb_cub_tv(T, k, i)], T->q[lb_cub_tv(T, k, (i + 1) % 3)], q);
            if (i == 0 || d < dmin) {
                dmin = d;
                emin = i;
            }
        }
        if (best < 0 || dmin > bd) {
            best = k;
            bd = dmin;
            bedge = emin;
        }
    }
    if (bd < -R(4) * T->eps)
        return -1;
    if (bd <= T->eps) {
        int a = lb_cub_tv(T, best, bedge), b = lb_cub_tv(T, best, (bedge + 1) % 3);
        real2 e = T->q[b] - T->q[a];
        real s = clamp(dot(q - T->q[a], e) / dot(e, e), R(0), R(1));
        int n = lb_cub_add(T, T->p[a] + (T->p[b] - T->p[a]) * s, u, v);
        lb_cub_split_edge(T, best, bedge, n);
        return n;
    }
    int n = lb_cub_add(T, p, u, v);
    int a = lb_cub_tv(T, best, 0), b = lb_cub_tv(T, best, 1), c = lb_cub_tv(T, best, 2);
    lb_cub_set(T, best, a, b, n);
    lb_cub_set(T, T->nt++, b, c, n);
    lb_cub_set(T, T->nt++, c, a, n);
    return n;
}

/* The initial triangulation: a fan around p (paper 5.2; thesis Fig. 5.8),
 * with p's three cases decided by the same tolerances as lb_cub_insert: at a
 * vertex (fan from it), on an edge (a new hull vertex, fan of h - 1
 * triangles), inside (fan of h triangles). Returns p's sample index. */
LB_FN int lb_cub_fan_point(lb_cub* T, real3 p, real3 u, real3 v)
{
    lb_cub_fan_vertex(T, 0);
    int s = lb_cub_insert(T, p, u, v);
    if (s < 0)
        return -1;
    if (s < T->nh) {
        lb_cub_fan_vertex(T, s);
        return s;
    }
    /* A new sample: inside or on a hull edge. Rebuild as the fan around it. */
    int h = T->nh;
    real2 q = T->q[s];
    int edge = -1;
    for (int i = 0; i < h; ++i)
        if (lb_cub_side(T->q[i], T->q[(i + 1) % h], q) <= T->eps)
            edge = i;
    T->nt = 0;
    for (int i = 0; i < h; ++i)
        if (i != edge)
            lb_cub_set(T, T->nt++, s, i, (i + 1) % h);
    return s;
}

/* Lawson's flip algorithm (thesis Alg. 5.1) by sweeps over the interior
 * edges until none violates the in-circle test by more than the tolerance.
 * A flip also needs the quadrilateral to be strictly convex (both new
 * triangles positive by more than eps), so no flip can invert a triangle. */
LB_FN void lb_cub_delaunay(lb_cub* T)
{
    for (int again = 1; again && T->flips < LB_CUB_MAXFLIPS;) {
        again = 0;
        for (int k = 0; k < T->nt && T->flips < LB_CUB_MAXFLIPS; ++k)
            for (int i = 0; i < 3; ++i) {
                int a = lb_cub_tv(T, k, i), b = lb_cub_tv(T, k, (i + 1) % 3), c = lb_cub_tv(T, k, (i + 2) % 3);
                int e2;
                int k2 = lb_cub_find_edge(T, b, a, &e2);
                if (k2 < k) /* hull edge, or seen from the other side already */
                    continue;
                int d = lb_cub_tv(T, k2, (e2 + 2) % 3);
                if (lb_cub_incircle(T, a, b, c, d) <= lb_cub_incircle_tol())
                    continue;
                /* new triangles (a, d, c) and (d, b, c) */
                if (lb_cub_side(T->q[d], T->q[c], T->q[a]) <= T->eps ||
                    lb_cub_side(T->q[c], T->q[d], T->q[b]) <= T->eps)
                    continue;
                lb_cub_set(T, k, a, d, c);
                lb_cub_set(T, k2, d, b, c);
                T->flips++;
                again = 1;
                break;
            }
    }
}

/* Sign that turns lb_tri_solid_angle of a counter-clockwise (in q) triangle
 * into its positive area: det(p_a, p_b, p_c) = 2 area (u x v) . p_a. */
LB_FN real lb_cub_orientation(const lb_cub* T, real3 u, real3 v)
{
    return (T->ns > 0 && dot(cross(u, v), T->p[0]) < R(0)) ? R(-1) : R(1);
}

/* Per-sample weights w[0..ns) of the weighting scheme (LB_CUB_SAMPLE,
 * _AVERAGE, _DOTOUT; header comment), E = sum_i w_i L_i. nL: the light's
 * normal. Returns the sum of the triangles' solid angles. */
LB_FN real lb_cub_weights(const lb_cub* T, real3 u, real3 v, real3 nL, real3 nx, int weighting, real* w)
{
    real sgn = lb_cub_orientation(T, u, v);
    real g[LB_CUB_MAXS], c[LB_CUB_MAXS];
    for (int i = 0; i < T->ns; ++i) {
        w[i] = R(0);
        real r = T->r[i] > R(0) ? T->r[i] : R(1);
        g[i] = fmax(R(0), dot(nx, T->p[i]) / r);
        c[i] = fmax(fabs(dot(nL, T->p[i])) / r, lb_real_eps());
    }
    real total = R(0);
    for (int k = 0; k < T->nt; ++k) {
        int a = lb_cub_tv(T, k, 0), b = lb_cub_tv(T, k, 1), cc = lb_cub_tv(T, k, 2);
        real om = sgn * lb_tri_solid_angle(T->p[a], T->p[b], T->p[cc]);
        total += om;
        real third = om / R(3);
        if (weighting == LB_CUB_SAMPLE) {
            w[a] += third * g[a];
            w[b] += third * g[b];
            w[cc] += third * g[cc];
        } else if (weighting == LB_CUB_AVERAGE) {
            real gm = third * (g[a] + g[b] + g[cc]) / R(3);
            w[a] += gm;
            w[b] += gm;
            w[cc] += gm;
        } else {
            real gm = om * (g[a] + g[b] + g[cc]) / (R(3) * (c[a] + c[b] + c[cc]));
            w[a] += gm * c[a];
            w[b] += gm * c[b];
            w[cc] += gm * c[cc];
        }
    }
    return total;
}

/* lb_polygon_centroid (area barycentre, continuous under clipping): dynamic.h. */

/* The dynamic points -- lb_closest_point_polygon (polygon.h), lb_normal_point
 * and lb_mrp (dynamic.h) -- are the ones the cp/np/mrp baselines use. */

/* The whole geometric step for the shading point x (world) with normal nx:
 * plane shift, (tilted) horizon clip, dynamic points, triangulation, weights
 * (of opt: triangulation, weighting, dynamic; of tun: plane_eps, horizon_eps).
 * On return T holds the samples (positions relative to the shifted x) and
 * triangles, w[0..T->ns) the weights, *elam the exact Lambert irradiance of
 * the clipped light at unit radiance. Returns the sum of the triangles' solid
 * angles (0 when nothing of the light is above the horizon). */
LB_FN real lb_cubature_setup(lb_cub* T, lb_light L, real3 x, real3 nx, lb_cub_options opt, lb_cub_tunables tun,
                             real* w, real* elam)
{
    int dynamic = opt.dynamic;
    x = lb_plane_shift(L, x, tun.plane_eps);
    real3 poly[LB_MAXV];
    lb_light_corners(L, poly);
    for (int i = 0; i < 4; ++i)
        poly[i] -= x;
    int n = lb_clip_polygon(poly, 4, nx, tun.horizon_eps);
    *elam = n >= 3 ? lb_polygon_irradiance_lambert(poly, n, nx) : R(0);
    if (lb_cub_init(T, poly, n, L.u, L.v) < 3) {
        T->nt = 0;
        return R(0);
    }
    real3 dyn[4];
    int nd = 0;
    /* CP by the linear-test clamp: squared distances cannot separate a vertex
     * from an edge point closer than |x - CP| sqrt(ulp) (7e-4 at 2 m in
     * float), and CP hopping onto the corner changed the Delaunay
     * triangulation of nearby dynamic points. NP without skew. */
    int where;
    real3 cp = lb_closest_point_polygon(poly, n, L.n, R3(0, 0, 0), &where);
    real3 np = (dynamic & (LB_CUB_NP | LB_CUB_MRP)) ? lb_normal_point(poly, n, L.n, nx, R(0)) : cp;
    if (dynamic & LB_CUB_CP)
        dyn[nd++] = cp;
    if (dynamic & LB_CUB_MRP)
        dyn[nd++] = lb_mrp(poly, n, L.n, cp, np);
    if (dynamic & LB_CUB_NP)
        dyn[nd++] = np;
    if (dynamic & LB_CUB_BARY)
        dyn[nd++] = lb_polygon_centroid(poly, n);
    if (nd > 0) {
        if (lb_cub_fan_point(T, dyn[0], L.u, L.v) < 0)
            lb_cub_fan_vertex(T, 0);
    } else {
        lb_cub_fan_vertex(T, 0);
    }
    for (int i = 1; i < nd; ++i)
        lb_cub_insert(T, dyn[i], L.u, L.v);
    /* Static samples at fixed points of the light, inserted like further
     * dynamic points: one on a sample (a corner, a dynamic point) merges with
     * it, one on an edge splits the edge, one outside what the horizon leaves
     * is dropped (lb_cub_insert). */
    if (opt.nstatic > 0) {
        real st[8] = {tun.s1, tun.t1, tun.s2, tun.t2, tun.s3, tun.t3, tun.s4, tun.t4};
        for (int k = 0; k < opt.nstatic && k < 4; ++k)
            lb_cub_insert(T,
                          L.c + L.u * ((st[2 * k] - R(0.5)) * L.w) + L.v * ((st[2 * k + 1] - R(0.5)) * L.l) - x,
                          L.u, L.v);
    }
    if (opt.triangulation == LB_CUB_DELAUNAY)
        lb_cub_delaunay(T);
    return lb_cub_weights(T, L.u, L.v, L.n, nx, opt.weighting, w);
}

/* Cubature irradiance (lux) at x: lb_cubature_setup, then the photometric
 * lookups; opt.formfactor: the normalization of step 6. *ntri and *nflips
 * receive the statistics. Two placement tunables (searched by `lumibench
 * tune`; lb_cub_plain_tunables' 0 and 1 are the plain method, bit for bit):
 *   corner_inset  the hull samples (the clipped light's corners) look the
 *                 radiance up at p + corner_inset (c - p), c the mean of
 *                 the clipped light's corners; the triangles and with them the
 *                 weights stay those of the corners (a quadrature-node shift
 *                 away from the grazing directions at the light's rim);
 *   dyn_weight    the weights of the dynamic samples are scaled by it and
 *                 all weights rescaled to the same sum, so the estimate
 *                 stays a weighted mean of the radiance times the same
 *                 total cosine-weighted solid angle.
 * blend_dist, area_q and area_sin are the kernel's (lb_blend_weight,
 * lb_area_weight), not read here. */
LB_FN real lb_cubature_irradiance(__global const float* lum, lb_light L, real3 x, real3 nx, lb_cub_options opt,
                                  lb_cub_tunables tun, int* ntri, int* nflips)
{
    lb_cub T;
    real w[LB_CUB_MAXS];
    real elam;
    lb_cubature_setup(&T, L, x, nx, opt, tun, w, &elam);
    *ntri = T.nt;
    *nflips = T.flips;
    real dyn_weight = tun.dyn_weight, corner_inset = tun.corner_inset;
    if (dyn_weight != R(1) && T.ns > T.nh) {
        real before = R(0), after = R(0);
        for (int i = 0; i < T.ns; ++i) {
            before += w[i];
            if (i >= T.nh)
                w[i] *= dyn_weight;
            after += w[i];
        }
        real k = after > R(0) ? before / after : R(0);
        for (int i = 0; i < T.ns; ++i)
            w[i] *= k;
    }
    real3 c = R3(0, 0, 0);
    if (corner_inset != R(0)) {
        for (int i = 0; i < T.nh; ++i)
            c += T.p[i];
        c /= (real)(T.nh > 0 ? T.nh : 1);
    }
    real e = R(0), ws = R(0);
    for (int i = 0; i < T.ns; ++i) {
        real3 p = T.p[i];
        if (corner_inset != R(0) && i < T.nh)
            p += corner_inset * (c - p);
        if (w[i] != R(0))
            e += w[i] * lb_radiance_from(lum, L, p);
        ws += w[i];
    }
    if (opt.formfactor)
        return ws > R(0) ? elam * e / ws : R(0);
    return e;
}

/* Far-field blend (thesis 6.6 proposes blending the cubature into MCI with
 * distance; the blend_dist tunable). lb_grid_mc_irradiance: the area form of
 * docs/design.md section 1 on the midpoints of a k x k grid over the light,
 * E = (1/k^2) sum I(d_i) max(0, n_x . w_i) / r_i^2 -- a fixed, deterministic
 * point set (an MCI-k^2 with stratified midpoints), accurate once the light
 * is small in view. */
LB_FN real lb_grid_mc_irradiance(__global const float* lum, lb_light L, real3 x, real3 nx, int k)
{
    real e = R(0);
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
            real s = ((real)i + R(0.5)) / (real)k - R(0.5), t = ((real)j + R(0.5)) / (real)k - R(0.5);
            real3 p = L.c + L.u * (s * L.w) + L.v * (t * L.l) - x; /* sample relative to x */
            real r2 = dot(p, p);
            if (r2 <= R(0))
                continue;
            real r = sqrt(r2);
            real cx = dot(nx, p) / r;
            if (cx <= R(0))
                continue;
            e += lb_intensity_local(lum, lb_to_light_frame(L, -p / r)) * cx / r2;
        }
    return e / (real)(k * k);
}

/* Blend weight of the grid MC at distance dist from the light's centre: 0 up
 * to blend_dist, linear to 1 at 1.5 blend_dist. */
LB_FN real lb_blend_weight(real dist, real blend_dist)
{
    return clamp((dist - blend_dist) / (R(0.5) * blend_dist), R(0), R(1));
}

/* The straight-line cubature of an unclipped rectangle:
 * cubature_lanes.inc, here one pixel per call (lb_cub_rect_fan); the 8-lane
 * form is included by kernels/cubature.cl. */
#include "lanes1.h"
#include "cubature_lanes.inc"
#include "lanes_end.h"
