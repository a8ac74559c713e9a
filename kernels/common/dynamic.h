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

/* Machine epsilon of real (a function, not a macro: the host includes this
 * header once per precision). */
LB_FN real lb_real_eps(void)
{
#if LB_REAL_IS_DOUBLE
    return R(2.220446049250313e-16);
#else
    return R(1.1920929e-7);
#endif
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
    return lb_intensity_local(lum, dl) / (lb_light_area(L) * c);
}

/* Normal point (paper 4.2, thesis 4.2, Drobot 2014) of the receiver with
 * normal nx at the origin: where the ray along nx meets the light's plane
 * (normal nL, through the polygon p[0..n), the clipped light relative to x),
 * clamped to the polygon (lb_closest_point_polygon).
 * skew > 0 (the np/mrp baselines, thesis 4.2): with n_f the light normal
 * facing x, the ray misses the plane or meets it behind x when nx . n_f >= 0;
 * nx is skewed whenever nx . n_f > -skew, towards the direction
 * nx - n_f (nx . n_f + skew), so the point moves continuously as nx turns.
 * skew <= 0 (the cubature): no skew; when the ray misses the plane (or meets
 * it farther than 1e3 light sizes), a point that far along nx projected onto
 * the plane is clamped instead: the limit of the hit point as the ray turns
 * parallel to the plane, to 1e-3 of the light's size. */
LB_FN real3 lb_normal_point(const real3* p, int n, real3 nL, real3 nx, real skew)
{
    real dl = dot(nL, p[0]); /* signed distance of the plane from x along nL */
    real3 dir = nx;
    if (skew > R(0)) {
        real3 nf = dl > R(0) ? -nL : nL; /* points from the light towards x */
        real a = dot(nx, nf);
        if (a > -skew)
            dir = normalize(nx - nf * (a + skew));
    }
    real dn = dot(nL, dir);
    real size = R(0);
    for (int i = 1; i < n; ++i)
        size = fmax(size, length(p[i] - p[0]));
    real big = R(1e3) * (fabs(dl) + size);
    real3 target;
    if (dn * dl > R(0) && dl / dn < big) {
        target = dir * (dl / dn);
    } else {
        real3 tg = dir - nL * dn;
        real lt = length(tg);
        target = nL * dl + (lt > R(0) ? tg * (big / lt) : R3(0, 0, 0));
    }
    int where;
    return lb_closest_point_polygon(p, n, nL, target, &where);
}

/* Most representative point (Drobot 2014, as adapted in paper 4.2): the light
 * plane hit by the ray along the half vector of the directions to the closest
 * point cp and the normal point np, clamped to the polygon p[0..n) (plane
 * normal nL); cp when that ray misses the plane. */
LB_FN real3 lb_mrp(const real3* p, int n, real3 nL, real3 cp, real3 np)
{
    real lc = length(cp), ln = length(np);
    if (!(lc > R(0)) || !(ln > R(0)))
        return cp;
    real3 h = cp / lc + np / ln;
    real dl = dot(nL, p[0]);
    real dn = dot(nL, h);
    if (!(dn * dl > R(0)))
        return cp;
    int where;
    return lb_closest_point_polygon(p, n, nL, h * (dl / dn), &where);
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
