/* scene.h -- the light and the image grid of docs/design.md section 2, shared by host
 * and kernels. Kernels receive the scene as a small array of reals P (one
 * buffer, so float and double kernels take the same argument list), laid out
 * by the indices below: the one declaration of the layout, which
 * host/scene/scene.cpp (Scene::params) fills by the same names
 * (tests/scene: each field at its index). The receiver is the plane z = 0
 * seen from above. */

#define LB_P_C 0       /* light centre (3 reals) */
#define LB_P_U 3       /* u, the width axis (3) */
#define LB_P_V 6       /* v = cross(u, n_L), the length axis (3) */
#define LB_P_N 9       /* n_L, where the light emits (3) */
#define LB_P_W 12      /* width W along u */
#define LB_P_L 13      /* length L along v */
#define LB_P_EXTENT 14 /* side S of the square image */
#define LB_P_RES 15    /* resolution N (pixels per side) */
#define LB_P_NX 16     /* receiver normal n_x (3) */
#define LB_P_KIND 19   /* what the image shows: LB_KIND_* below */
#define LB_P_EYE 20    /* specular: the eye point (3) */
#define LB_P_ALPHA 23  /* specular: GGX roughness alpha */
#define LB_P_ALBEDO 24 /* indirect: albedo of walls and ceiling */
#define LB_P_SHAPE 25  /* the light's outline: LB_SHAPE_* below */
#define LB_SCENE_SIZE 28

#define LB_SHAPE_RECT 0 /* the rectangle W x L (docs/design.md section 2) */
#define LB_SHAPE_DISK 1 /* the ellipse inscribed in it: a disk of diameter D when W = L = D */

#define LB_KIND_DIFFUSE 0  /* direct irradiance on the floor (docs/design.md section 2) */
#define LB_KIND_SPECULAR 1 /* luminance of a glossy floor towards the eye (docs/design.md section 8) */
#define LB_KIND_INDIRECT 2 /* one-bounce indirect irradiance on the floor (docs/design.md section 9) */
/* The room of the indirect scene (docs/design.md section 9): [-HALF, HALF]^2 x [0, HEIGHT] m,
 * the same values as kRoomHalf / kRoomHeight of host/scene/scene.h (a test
 * holds them equal). */
#define LB_ROOM_HALF 2.5
#define LB_ROOM_HEIGHT 3.0

typedef struct {
    real3 c, u, v, n; /* centre and frame: n_L points where the light emits; v = cross(u, n) */
    real w, l;        /* width along u, length along v (a disk's diameters) */
#ifdef __OPENCL_C_VERSION__
    int shape; /* LB_SHAPE_* */
#else
    int shape = LB_SHAPE_RECT;
#endif
} lb_light;

/* The light's area: W L, or pi W L / 4 for the disk. */
LB_FN real lb_light_area(lb_light L)
{
    return L.shape == LB_SHAPE_DISK ? R(0.25) * LB_PI * L.w * L.l : L.w * L.l;
}

LB_FN real3 lb_p3(__global const real* P, int i)
{
    return R3(P[i], P[i + 1], P[i + 2]);
}

LB_FN lb_light lb_scene_light(__global const real* P)
{
    lb_light L;
    L.c = lb_p3(P, LB_P_C);
    L.u = lb_p3(P, LB_P_U);
    L.v = lb_p3(P, LB_P_V);
    L.n = lb_p3(P, LB_P_N);
    L.w = P[LB_P_W];
    L.l = P[LB_P_L];
    L.shape = (int)P[LB_P_SHAPE];
    return L;
}

/* Corners in the order (-u,-v), (+u,-v), (+u,+v), (-u,+v). */
LB_FN void lb_light_corners(lb_light L, real3* p)
{
    real3 hu = L.u * (R(0.5) * L.w);
    real3 hv = L.v * (R(0.5) * L.l);
    p[0] = L.c - hu - hv;
    p[1] = L.c + hu - hv;
    p[2] = L.c + hu + hv;
    p[3] = L.c - hu + hv;
}

/* Receiver point at the centre of pixel (row, col), row 0 at the top (+y). */
LB_FN real3 lb_pixel_position(__global const real* P, int row, int col)
{
    real s = P[LB_P_EXTENT];
    real n = P[LB_P_RES];
    return R3(-R(0.5) * s + ((real)col + R(0.5)) * s / n,
              R(0.5) * s - ((real)row + R(0.5)) * s / n,
              R(0));
}

#ifdef __OPENCL_C_VERSION__
/* The one-pixel kernels' prologue: the work-item's pixel (col, row) of rows
 * row0 .. of the res x res image, its index px = row * res + col in the
 * output image, the scene's light, the pixel's receiver point x and its
 * normal nx; 0 when the work-item has no pixel (a partial last group).
 * lb_work_item_receiver drops (col, row); a kernel that also needs the
 * pixel's offsets in the light's frame (lb_corner_offset) keeps them. The
 * one kernel that cannot return early (mc.cl: a barrier per sample) has its
 * own. */
LB_FN int lb_work_item_receiver_cell(__global const real* P, int row0, int* col, int* row, int* px, lb_light* L,
                                     real3* x, real3* nx)
{
    *col = (int)get_global_id(0);
    *row = row0 + (int)get_global_id(1);
    int res = (int)P[LB_P_RES];
    if (*col >= res || *row >= res)
        return 0;
    *px = *row * res + *col;
    *L = lb_scene_light(P);
    *x = lb_pixel_position(P, *row, *col);
    *nx = lb_p3(P, LB_P_NX);
    return 1;
}

LB_FN int lb_work_item_receiver(__global const real* P, int row0, int* px, lb_light* L, real3* x, real3* nx)
{
    int col, row;
    return lb_work_item_receiver_cell(P, row0, &col, &row, px, L, x, nx);
}
#endif

/* The plane shift: a receiver point x closer than eps to the light's plane
 * moves along n_L to distance eps on its own side, the side of
 * s = n_L . (x - c) (s = 0 counts as in front). In the plane the radiance
 * I / (A |n_L . d|) of every sample is infinite while the solid angle it
 * multiplies is 0, and their product in rounding is anything (1e13-1e22 lux
 * seen); eps off the plane both are finite and their product the
 * irradiance there. The cubature, voronoi and ltc shift every receiver by
 * their tunable plane_eps. The other methods that weight a radiance by a
 * solid angle (structured, cp / np / mrp, point, engine, sh) are finite
 * beside the light in its plane, where the radiance's and the solid
 * angle's zeros cancel to rounding, and shift by LB_PLANE_EPS only the
 * receivers on the light itself (lb_plane_shift_on_light: the foot on n_L
 * within eps of the W x L box), where they gave 1e13-1e22 lux. The
 * straight-line forms shift the height h alike (lb_plane_shift_h,
 * scene_lanes.inc). */
#define LB_PLANE_EPS R(1e-3) /* metres: the cubature's default plane_eps */
LB_FN real3 lb_plane_shift(lb_light L, real3 x, real eps)
{
    real s = dot(L.n, x - L.c);
    if (fabs(s) < eps)
        x += L.n * ((s >= R(0) ? eps : -eps) - s);
    return x;
}

LB_FN real3 lb_plane_shift_on_light(lb_light L, real3 x, real eps)
{
    real3 d = x - L.c;
    int on = fabs(dot(d, L.u)) <= R(0.5) * L.w + eps && fabs(dot(d, L.v)) <= R(0.5) * L.l + eps;
    return on ? lb_plane_shift(L, x, eps) : x;
}

/* Direction d (world) expressed in the luminaire's photometric frame (u, v, n). */
LB_FN real3 lb_to_light_frame(lb_light L, real3 d)
{
    return R3(dot(d, L.u), dot(d, L.v), dot(d, L.n));
}

/* The receiver normal n_x (P[LB_P_NX ..]) in the light's frame (u, v, n_L). */
LB_FN void lb_receiver_normal_local(__global const real* P, real* au, real* av, real* an)
{
    real nxx = P[LB_P_NX], nxy = P[LB_P_NX + 1], nxz = P[LB_P_NX + 2];
    *au = nxx * P[LB_P_U] + nxy * P[LB_P_U + 1] + nxz * P[LB_P_U + 2];
    *av = nxx * P[LB_P_V] + nxy * P[LB_P_V + 1] + nxz * P[LB_P_V + 2];
    *an = nxx * P[LB_P_N] + nxy * P[LB_P_N + 1] + nxz * P[LB_P_N + 2];
}

/* lb_corner_offset(P, col, row, &ou, &ov, &on): scene_lanes.inc. */
#include "lanes1.h"
#include "scene_lanes.inc"
#include "lanes_end.h"

#if defined(__OPENCL_C_VERSION__) && !LB_REAL_IS_DOUBLE
/* Stores the eight pixels e of one row of an 8-lane kernel (lanes8.h) at
 * out[i ..], only the first `left` of them at the row's end. */
LB_FN void lb_store_x8(__global real* out, int i, int left, float8 e)
{
    if (left >= 8) {
        vstore8(e, 0, out + i);
        return;
    }
    float ev[8];
    vstore8(e, 0, ev);
    for (int j = 0; j < left; ++j)
        out[i + j] = ev[j];
}
#endif
