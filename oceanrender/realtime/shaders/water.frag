#version 330 core
// oceanrender's reference water shader: the dissertation's real-time model on the baked LUTs.
//
//   C      = G1 [T_refl F^gamma + C_water (1 - F^gamma)] + glint    (Eq. 20, glint added as a highlight;
//            G1: Smith's masking of the unresolved roughness at the view, as the path tracer's BSDF has it)
//   C_water = T0(h) + T1(h, l) * (R - R0)                            (Eq. 22; T0, T1 of Eq. 21 baked)
//   on the fraction B of foam: (1 - B) C + B foam_albedo * (sun + sky light), as the renderer blends them
//
// with F the Fresnel reflectance at n.v (LUT), T_refl the sky map in the mirror direction, h the depth
// of the water column, l the refracted view ray's path to the seafloor, R the seafloor albedo where it
// ends and R0 the LUTs' reference albedo. The ripple maps add the waves finer than the mesh: their
// resolved slopes tilt the normal, their unresolved slope variance stays roughness of the sun's glint
// (LEAN mapping, Olano & Baker 2010), and their refraction displaces the seafloor lookup (the
// dissertation's texture-coordinate perturbation).
//
// Interface (the same for any shader that `oceanrender validate-shader` grades; docs/realtime.md):
//   * one fragment per pixel of the reference view; the G-buffer is fetched at ivec2(gl_FragCoord.xy)
//     (texel (i, j) is pixel column i, row j counted from the top of the reference image);
//   * out vec4 frag_colour: rgb = linear display sRGB before the vision model's display response
//     (the units of the baked colour LUTs), alpha ignored;
//   * every uniform below is optional: the harness sets those the shader declares.
// World frame: z up, +x east, +y north; metres. Inf in the G-buffer means "none" (no seafloor, sky).
//
// Equation numbers: the dissertation named in the project issue (Eqs. 20-22); B. Walter et al.,
// "Microfacet models for refraction through rough surfaces", EGSR 2007 (Eqs. 20, 25, 27);
// M. Olano and D. Baker, "LEAN mapping", I3D 2010 (sec. 3).

// ---- G-buffer: RGBA32F, one texel per pixel, NEAREST --------------------------------------------
uniform sampler2D g_position;   // xyz: world position of the first hit [m]; w: kind (0 sky, 1 water, 2 land, 3 other)
uniform sampler2D g_normal;     // xyz: unit shading normal facing the camera [-]; w: cos_view = n.v [-]
uniform sampler2D g_view;       // xyz: unit camera-ray direction (camera -> scene) [-]; w: distance [m] (inf: sky)
uniform sampler2D g_water;      // x: depth h [m]; y: in-water path l [m] (both inf: no seafloor); z: rock [0, 1];
                                // w: Beckmann alpha of the surface at the hit (0: use u_alpha)
uniform sampler2D g_refracted;  // xyz: unit refracted direction (water pixels) [-]; w: fresh-foam coverage B [0, 1]

// ---- LUTs: float textures, LINEAR, CLAMP_TO_EDGE (sky: REPEAT in u); nodes at texel centres ------
uniform sampler2D lut_T0;       // 1 row, columns: depth h on the rational axis u = h/(h + depth_scale)
uniform sampler2D lut_T1;       // columns: path l (u = l/(l + path_scale)); rows: depth h (as T0)
uniform sampler2D lut_fresnel;  // 1 row, columns: mu = cos(theta) in [0, 1]; R: F(mu)
uniform sampler2D lut_sky;      // latitude-longitude: u = azimuth/2pi (clockwise from north), v = zenith/pi
uniform sampler2D lut_seafloor; // R: rock coverage over world x (columns) and y (rows); coastal sets only
uniform sampler2D ripple_moments;  // mipmapped, REPEAT: (s_x, s_y, s_x^2, s_y^2) of the ripple tile [-]
uniform sampler2D ripple_offsets;  // mipmapped, REPEAT: seafloor drift per metre of depth (dx, dy) [m/m]

uniform float u_depth_scale;       // s of the depth axis [m]
uniform float u_path_scale;        // s of the path axis [m]
uniform int u_has_seafloor;        // 1: lut_seafloor holds the floor's rock coverage
uniform vec4 u_seafloor_extent;    // x of the first and last column, y of the first and last row [m]
uniform int u_has_sand_rock;       // 1: R = mix(sand, rock, coverage); 0: R = R0 (open sea)
uniform vec3 u_reference_albedo;   // R0 (display RGB)
uniform vec3 u_sand_albedo;        // display RGB
uniform vec3 u_rock_albedo;        // display RGB
uniform float u_gamma;             // gamma of F^gamma (Eq. 20) [-]
uniform float u_n_water;           // refractive index [-]
uniform float u_alpha;             // Beckmann roughness of the waves finer than the finest mesh cell [-]
uniform vec3 u_sun_direction;      // unit direction to the sun
uniform vec3 u_sun_rgb;            // Phi(E_sun / pi), direct-normal sun (display RGB)
uniform vec3 u_sky_rgb;            // Phi(E_sky / pi), diffuse sky on a horizontal plane (display RGB)
uniform int u_glint;               // 1: add the sun's glint
uniform int u_masking;             // 1: weight Eq. 20 by Smith's G1(n.v) of the unresolved roughness
uniform int u_has_foam;            // 1: blend the G-buffer's foam coverage in
uniform vec3 u_foam_albedo;        // fresh foam's albedo (display RGB)
uniform float u_ripple_patch;      // side of the ripple tile [m]
uniform float u_ripple_strength;   // k: scale of the ripple slopes (0: none) [-]
uniform float u_ripple_mss;        // mean-square slope of the tile (top mip level) [-]
uniform float u_pixel_angle;       // angle of a pixel at the image centre [rad]

out vec4 frag_colour;

const float PI = 3.14159265358979;
const float HORIZON_Z = 1e-3;      // a mirror direction below the horizon is lifted to this z
const float MIN_NORMAL_Z = 0.2;    // steeper facets get no ripples
const float MIN_RAY_Z = 0.02;      // caps the footprint's stretch at grazing views
const float MIN_ALPHA = 0.02;      // roughness left when the ripples resolve everything

// Texture coordinate of the value at u in [0, 1] of an axis whose N texels hold the nodes i/(N-1).
float node_texcoord(float u, int n) { return (clamp(u, 0.0, 1.0) * float(n - 1) + 0.5) / float(n); }

// u = x/(x + s) of a rational axis; x = inf is u = 1.
float rational_u(float x, float s) { return isinf(x) ? 1.0 : max(x, 0.0) / (max(x, 0.0) + s); }

vec3 sample_1d(sampler2D lut, float u) {
    return texture(lut, vec2(node_texcoord(u, textureSize(lut, 0).x), 0.5)).rgb;
}

vec3 sample_2d(sampler2D lut, float u, float v) {
    ivec2 size = textureSize(lut, 0);
    return texture(lut, vec2(node_texcoord(u, size.x), node_texcoord(v, size.y))).rgb;
}

vec3 sky(vec3 d) {
    float u = fract(atan(d.x, d.y) / (2.0 * PI));
    float v = acos(clamp(d.z, -1.0, 1.0)) / PI;
    return texture(lut_sky, vec2(u, v)).rgb;
}

float fresnel(float mu) {
    return clamp(sample_1d(lut_fresnel, clamp(mu, 0.0, 1.0)).r, 0.0, 1.0);  // FRESNEL LOOKUP
}

float fresnel_exact(float c) {  // unpolarised Fresnel reflectance, air -> water, at cos(theta_i) = c
    float s2 = (1.0 - c * c) / (u_n_water * u_n_water);
    if (s2 >= 1.0) return 1.0;
    float ct = sqrt(1.0 - s2);
    float rs = (c - u_n_water * ct) / (c + u_n_water * ct);
    float rp = (u_n_water * c - ct) / (u_n_water * c + ct);
    return 0.5 * (rs * rs + rp * rp);
}

float beckmann_d(float cos_h, float alpha) {  // Walter et al. 2007, Eq. 25
    if (cos_h <= 0.0) return 0.0;
    float c2 = clamp(cos_h, 1e-6, 1.0);
    c2 *= c2;
    return exp(-(1.0 - c2) / (c2 * alpha * alpha)) / (PI * alpha * alpha * c2 * c2);
}

float smith_g1(float cos_v, float alpha) {  // Walter et al. 2007, Eq. 27
    float c = clamp(cos_v, 1e-6, 1.0);
    float a = c / (alpha * max(sqrt(1.0 - c * c), 1e-6));
    if (a >= 1.6) return 1.0;
    return (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a);
}

vec3 sun_glint(vec3 n, vec3 v, float alpha) {  // pi E_sun F(v.h) D G1 G1 / (4 n.v), Walter et al. 2007 Eq. 20
    vec3 s = u_sun_direction;
    vec3 h = normalize(v + s);
    float cos_v = dot(n, v), cos_s = dot(n, s);
    if (cos_v <= 0.0 || cos_s <= 0.0) return vec3(0.0);
    float F = fresnel_exact(clamp(dot(v, h), 0.0, 1.0));
    float value = F * beckmann_d(dot(n, h), alpha) * smith_g1(cos_v, alpha) * smith_g1(cos_s, alpha)
                  / (4.0 * max(cos_v, 1e-6));
    return PI * value * u_sun_rgb;
}

vec3 albedo(float rock) {
    return u_has_sand_rock == 1 ? mix(u_sand_albedo, u_rock_albedo, rock) : u_reference_albedo;
}

vec3 diffuse_light(vec3 n) {  // a white Lambertian surface: sun, and a uniform sky's (1 + n_z)/2
    return max(dot(n, u_sun_direction), 0.0) * u_sun_rgb + 0.5 * (1.0 + n.z) * u_sky_rgb;
}

float seafloor_rock(vec2 xy) {
    ivec2 size = textureSize(lut_seafloor, 0);
    float u = (xy.x - u_seafloor_extent.x) / (u_seafloor_extent.y - u_seafloor_extent.x);
    float v = (xy.y - u_seafloor_extent.z) / (u_seafloor_extent.w - u_seafloor_extent.z);
    return texture(lut_seafloor, vec2(node_texcoord(u, size.x), node_texcoord(v, size.y))).r;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 P = texelFetch(g_position, pixel, 0);
    vec4 N = texelFetch(g_normal, pixel, 0);
    vec4 D = texelFetch(g_view, pixel, 0);
    int kind = int(P.w + 0.5);
    vec3 ray = D.xyz;

    if (kind == 0) {  // sky: the map in the view direction (no sun disc)
        frag_colour = vec4(sky(ray), 1.0);
        return;
    }
    if (kind == 2) {  // land seen directly: Lambertian under the sun and the sky
        float rock = texelFetch(g_water, pixel, 0).z;
        frag_colour = vec4(albedo(rock) * diffuse_light(N.xyz), 1.0);
        return;
    }
    if (kind != 1) {
        frag_colour = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }

    // ---- water -------------------------------------------------------------------------------------
    vec4 W = texelFetch(g_water, pixel, 0);
    float h = W.x, l = W.y, rock = W.z;
    vec4 TB = texelFetch(g_refracted, pixel, 0);
    vec3 T = TB.xyz;
    float foam = u_has_foam == 1 ? clamp(TB.w, 0.0, 1.0) : 0.0;
    vec3 n = N.xyz;
    float alpha_surface = W.w > 0.0 ? W.w : u_alpha;  // a mesh with alpha per vertex: coarser, rougher far away
    float mu = clamp(N.w, 0.0, 1.0);

    // Ripples: LEAN moments at the level of the pixel's footprint.
    int texels = textureSize(ripple_moments, 0).x;
    float texel = u_ripple_patch / float(texels);
    float footprint = D.w * u_pixel_angle / max(abs(ray.z), MIN_RAY_Z);
    float top = log2(float(texels));
    float lod = clamp(log2(max(footprint / texel, 1e-30)), 0.0, top);
    vec2 st = fract(P.xy / u_ripple_patch) + 0.5 / float(texels);
    vec4 m = textureLod(ripple_moments, st, lod);
    vec2 drift = u_ripple_strength * textureLod(ripple_offsets, st, lod).xy;
    float k = u_ripple_strength;
    if (n.z >= MIN_NORMAL_Z) {
        n = normalize(vec3(n.xy / n.z - k * m.xy, 1.0));
    }
    float unresolved = max(m.z + m.w - dot(m.xy, m.xy), 0.0);
    float alpha = sqrt(max(alpha_surface * alpha_surface - k * k * (u_ripple_mss - unresolved),
                           MIN_ALPHA * MIN_ALPHA));
    mu = clamp(dot(n, -ray), 0.0, 1.0);

    // The seafloor where the ripple-refracted ray meets it (texture-coordinate perturbation).
    bool floor_hit = !isinf(l);
    if (u_has_seafloor == 1 && floor_hit) {
        vec3 bottom = P.xyz + l * T;
        rock = seafloor_rock(bottom.xy + l * abs(T.z) * drift);
    }

    // Eq. 20: the reflected sky and the light from the water, mixed by F^gamma.
    float F = fresnel(mu);
    float Fc = pow(F, u_gamma);
    vec3 reflected = ray + 2.0 * mu * n;
    reflected.z = max(reflected.z, HORIZON_Z);
    vec3 T_refl = sky(normalize(reflected));
    // Eqs. 21-22: T0, T1 baked over depth h and path l.
    float uh = rational_u(h, u_depth_scale);
    vec3 T0 = sample_1d(lut_T0, uh);
    vec3 T1 = floor_hit ? sample_2d(lut_T1, rational_u(l, u_path_scale), uh) : vec3(0.0);
    vec3 C_water = T0 + T1 * (albedo(rock) - u_reference_albedo);
    vec3 colour = T_refl * Fc + C_water * (1.0 - Fc);
    if (u_masking == 1) colour *= smith_g1(mu, alpha);
    if (u_glint == 1) colour += sun_glint(n, -ray, alpha);
    colour = mix(colour, u_foam_albedo * diffuse_light(n), foam);
    frag_colour = vec4(colour, 1.0);
}
