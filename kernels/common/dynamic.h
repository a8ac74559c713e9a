/* dynamic.h -- emitted radiance and the dynamic sample points of paper 4.2 /
 * thesis 4.2 (closest point CP, normal point NP, most representative point
 * MRP), on a polygon already clipped to the receiver's horizon.
 * Compiles as OpenCL C and C++ (see vec.h). All positions are relative to the
 * receiver point x (x is the origin). */

/* Area centroid of the convex planar polygon p[0..n) (the vertex mean when it
 * has no area). */
LB_FN real3 lb_polygon_centroid(const real3* p, int n)
{
    real3 s = R3(0, 0, 0);
    real a = R(0);
    for (int i = 1; i + 1 < n; ++i) {
        real w = length(cross(p[i] - p[0], p[i + 1] - p[0]));
        s += (p[0] + p[i] + p[i + 1]) * (w / R(3));
        a += w;
    }
    if (a > R(0))
        return s / a;
    real3 m = R3(0, 0, 0);
    for (int i = 0; i < n; ++i)
        m += p[i];
    return n > 0 ? m / (real)n : m;
}

/* Emitted radiance of the photometric light towards the origin from the point
 * p on the light (paper Eq. 2): L_e(d) = I(d) / (A |n_L . d|), d = -p / |p| the
 * emission direction, A the light's (unclipped) area.
 * In the light's plane |n_L . d| = 0 while the solid angle the callers multiply
 * by is 0 too (thesis 6.6's "contradiction"): I / 0 = inf (or 0 / 0 = NaN)
 * times 0 made NaN pixels. Only an exact (or underflowing) zero is cut off
 * here, to radiance 0: a near-plane |n_L . d| of rounding size (1e-8 in float
 * for a vertical light, whose n_L is tilted by cos(pi/2) = -4e-8) must stay,
 * since the solid angle then has the same rounding-size factor (to relative
 * eps, see lb_tri_solid_angle) and the product is the estimator's true
 * near-plane value; flooring it at eps, as first tried, made float and double
 * disagree by 30 % on that pixel row (lumibench stability, plane_diffuse). */
LB_FN real lb_radiance_from(__global const float* lum, lb_light L, real3 p)
{
    real3 d = -normalize(p);
    real3 dl = lb_to_light_frame(L, d);
    real c = fabs(dl.z);
#if LB_REAL_IS_DOUBLE
    if (c < R(1e-200))
#else
    if (c < R(1e-20)) /* I / (A c) < 1e25 / A: finite for every validated light */
#endif
        return R(0);
    return lb_intensity_local(lum, dl) / (L.w * L.l * c);
}

/* The light normal turned towards the origin: the side of the light x sees. */
LB_FN real3 lb_facing_normal(lb_light L, real3 c_rel)
{
    return dot(c_rel, L.n) > R(0) ? -L.n : L.n;
}

/* Intersection of the ray t * dir (t > 0) with the plane through q with
 * normal nf; *ok = 0 when the ray does not reach the plane. */
LB_FN real3 lb_ray_plane(real3 dir, real3 q, real3 nf, int* ok)
{
    real den = dot(dir, nf);
    real t = den != R(0) ? dot(q, nf) / den : R(-1);
    *ok = t > R(0) ? 1 : 0;
    return dir * t;
}

/* Normal point (thesis 4.2): where the ray from x along the receiver normal
 * nx meets the light plane (through c_rel, normal L.n), clamped to the polygon
 * p[0..n) (the clipped light). With n_f the light normal facing x, the ray
 * misses the plane or meets it behind x when nx . n_f >= 0; the thesis skews
 * nx towards the plane then. Here nx is skewed whenever nx . n_f > -skew, to
 * the direction whose component along n_f is exactly -skew (skew > 0), so the
 * point moves continuously as nx turns. */
LB_FN real3 lb_normal_point(const real3* p, int n, lb_light L, real3 c_rel, real3 nx, real skew)
{
    real3 nf = lb_facing_normal(L, c_rel); /* points from the light towards x */
    real3 dir = nx;
    real a = dot(nx, nf);
    if (a > -skew)
        dir = normalize(nx - nf * (a + skew));
    int ok = 0;
    real3 q = lb_ray_plane(dir, c_rel, nf, &ok);
    if (!ok)
        q = c_rel; /* cannot happen after the skew; the centre is a safe fallback */
    int where = 0;
    return lb_closest_point_polygon(p, n, L.n, q, &where);
}

/* Most representative point (Drobot 2014, as adapted in paper 4.2): the light
 * plane hit by the half-vector of the directions to the (clamped) closest and
 * normal points, clamped to the polygon again. */
LB_FN real3 lb_mrp(const real3* p, int n, lb_light L, real3 c_rel, real3 cp, real3 np)
{
    real3 h = normalize(cp) + normalize(np);
    real3 nf = lb_facing_normal(L, c_rel);
    int ok = 0;
    real3 q = lb_ray_plane(h, c_rel, nf, &ok);
    if (!ok)
        q = cp;
    int where = 0;
    return lb_closest_point_polygon(p, n, L.n, q, &where);
}

/* The light's corners relative to x, clipped to the horizon of normal nx
 * (dot(nx, p) >= 0); returns the vertex count (0: the light is below the
 * horizon). */
LB_FN int lb_clipped_light(lb_light L, real3 x, real3 nx, real3* p)
{
    lb_light_corners(L, p);
    for (int k = 0; k < 4; ++k)
        p[k] -= x;
    return lb_clip_polygon(p, 4, nx, R(0));
}
