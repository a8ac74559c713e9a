/* spherical.h -- solid angles and exact irradiance of polygons seen from a point.
 * Compiles as OpenCL C and C++ (see vec.h). Directions need not be normalised. */

/* Signed solid angle of the spherical triangle (a, b, c) seen from the origin,
 * positive when det(a, b, c) > 0. Van Oosterom & Strackee (1983) in atan2 form
 * on unnormalised vectors: the result converges to 0 as the triangle
 * degenerates (two equal vertices or three coplanar with the origin), which the
 * cubature needs for the thin triangles next to the closest point (paper 5.2). */
LB_FN real lb_tri_solid_angle(real3 a, real3 b, real3 c)
{
    real la = length(a), lb = length(b), lc = length(c);
    /* det(a, b, c) = a . ((b - a) x (c - a)). For a small far triangle (size s
     * at distance d) a . (b x c) cancels: b x c ~ d s carries rounding errors
     * ~ eps d^2, so det ~ d s^2 came out with relative error eps (d/s)^2 (a
     * 1 mm light at 1 m: 0.12 in float, the far-field / tiny-light failures of
     * lumibench stability). The edge vectors are formed first (exact for
     * nearby vertices), their cross product ~ s^2 is accurate to eps, and the
     * determinant to eps relative. */
    real num = dot(a, cross(b - a, c - a));
    real den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    return R(2) * atan2(num, den);
}

/* Solid angle of the convex polygon p[0..n) (positions relative to the viewing
 * point), any orientation: a fan of signed triangles, then the magnitude. */
LB_FN real lb_polygon_solid_angle(const real3* p, int n)
{
    real s = R(0);
    for (int i = 1; i + 1 < n; ++i)
        s += lb_tri_solid_angle(p[0], p[i], p[i + 1]);
    return fabs(s);
}

/* Angle between two directions, accurate also near 0 and pi (acos is not). */
LB_FN real lb_angle_between(real3 a, real3 b)
{
    return atan2(length(cross(a, b)), dot(a, b));
}

/* Irradiance at the origin, receiver normal nx, from the convex polygon
 * p[0..n) (relative positions, entirely on the positive side of nx: clip
 * first) of unit Lambertian radiance: Lambert's formula (Baum et al. 1989),
 *   E = 1/2 | sum_i Theta_i  nx . (p_i x p_i+1) / |p_i x p_i+1| |,
 * Theta_i the angle subtended by edge i. Multiply by the radiance for lux. */
LB_FN real lb_polygon_irradiance_lambert(const real3* p, int n, real3 nx)
{
    real s = R(0);
    for (int i = 0; i < n; ++i) {
        real3 a = p[i];
        real3 b = p[(i + 1 == n) ? 0 : i + 1];
        real3 c = cross(a, b);
        real lc = length(c);
        /* An edge whose great circle passes through nx's origin subtends no
         * area: its term is 0 (Theta_i -> 0 faster than lc). */
        if (lc > R(0))
            s += atan2(lc, dot(a, b)) * dot(nx, c) / lc;
    }
    return R(0.5) * fabs(s);
}
