// The realistic profile's surface pass: the same depth, normal and id outputs as `fs_surface`
// (computed the same way, so those modalities are identical in both profiles), and a colour
// made of procedural materials lit by the home's sun (with shadow maps), its sky and ground,
// and its rooms' lamps, tone-mapped.

struct Lights {
    // Camera frame to world.
    camera_to_world: mat4x4<f32>,
    // World to the shadow maps' clip spaces.
    static_shadow: mat4x4<f32>,
    dynamic_shadow: mat4x4<f32>,
    // World to the sky map's (the fixed geometry seen from straight above).
    sky_shadow: mat4x4<f32>,
    // World to the main lamp's map (in perspective, looking down).
    lamp_shadow: mat4x4<f32>,
    // Toward the sun.
    sun: vec4<f32>,
    sun_color: vec4<f32>,
    // Ambient from above; w: exposure.
    sky: vec4<f32>,
    ground: vec4<f32>,
    // x, y, z, w: whether the sky, the static, the dynamic and the lamp's map hold anything.
    counts: vec4<u32>,
    lamp_position: array<vec4<f32>, 8>,
    lamp_color: array<vec4<f32>, 8>,
    // The footprint each lamp lights: min x, min y, max x, max y.
    lamp_room: array<vec4<f32>, 8>,
    // x: how much of the materials' normal detail is drawn (1 or 0); y, z, w: padding.
    detail: vec4<f32>,
};

@group(1) @binding(0) var<uniform> lights: Lights;
@group(1) @binding(1) var static_map: texture_depth_2d;
@group(1) @binding(2) var dynamic_map: texture_depth_2d;
@group(1) @binding(3) var shadow_sampler: sampler_comparison;
@group(1) @binding(4) var sky_map: texture_depth_2d;
@group(1) @binding(5) var lamp_map: texture_depth_2d;

struct RealisticVertex {
    @builtin(position) clip: vec4<f32>,
    @location(0) camera: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) @interpolate(flat) color: vec4<f32>,
    @location(3) @interpolate(flat) ids: vec2<u32>,
    @location(4) world: vec3<f32>,
    @location(5) local: vec3<f32>,
    @location(6) @interpolate(flat) extent: vec3<f32>,
    @location(7) @interpolate(flat) surface: vec2<u32>,
};

@vertex
fn vs_realistic(v: VertexIn) -> RealisticVertex {
    var out: RealisticVertex;
    let placed = place(v);
    out.clip = placed.clip;
    out.camera = placed.camera;
    out.normal = placed.normal;
    out.color = v.color;
    out.ids = v.ids;
    out.world = v.position;
    out.local = v.local;
    out.extent = v.extent;
    out.surface = v.surface;
    return out;
}

// ---- noise ----

fn mix_bits(x: u32) -> u32 {
    var v = x * 747796405u + 2891336453u;
    v = ((v >> ((v >> 28u) + 4u)) ^ v) * 277803737u;
    return (v >> 22u) ^ v;
}

// A number in [0, 1] for a lattice point and a seed.
fn lattice(c: vec3<i32>, seed: u32) -> f32 {
    let h = mix_bits((bitcast<u32>(c.x) * 73856093u) ^ (bitcast<u32>(c.y) * 19349663u) ^ (bitcast<u32>(c.z) * 83492791u) ^ seed);
    return f32(h >> 8u) * (1.0 / 16777215.0);
}

// A number in [0, 1] for a corner's hashed coordinates and a seed (as `lattice`, with the
// coordinates' products made by the caller).
fn corner(x: u32, y: u32, z: u32, seed: u32) -> f32 {
    return f32(mix_bits(x ^ y ^ z ^ seed) >> 8u) * (1.0 / 16777215.0);
}

// Smooth value noise in [0, 1]. The corners' products are made once and stepped by addition
// (what `lattice` multiplies anew at each of the eight corners): noise is most of a pattern's
// cost.
fn noise(p: vec3<f32>, seed: u32) -> f32 {
    let i = vec3<i32>(floor(p));
    let f = fract(p);
    let u = f * f * (3.0 - 2.0 * f);
    let x0 = bitcast<u32>(i.x) * 73856093u;
    let y0 = bitcast<u32>(i.y) * 19349663u;
    let z0 = bitcast<u32>(i.z) * 83492791u;
    let x1 = x0 + 73856093u;
    let y1 = y0 + 19349663u;
    let z1 = z0 + 83492791u;
    let x00 = mix(corner(x0, y0, z0, seed), corner(x1, y0, z0, seed), u.x);
    let x10 = mix(corner(x0, y1, z0, seed), corner(x1, y1, z0, seed), u.x);
    let x01 = mix(corner(x0, y0, z1, seed), corner(x1, y0, z1, seed), u.x);
    let x11 = mix(corner(x0, y1, z1, seed), corner(x1, y1, z1, seed), u.x);
    return mix(mix(x00, x10, u.y), mix(x01, x11, u.y), u.z);
}


// ---- patterns ----
// Each pattern is two noise lookups at frequencies of its own, then a little arithmetic. Why so
// lean: a CPU rasterizer runs every branch for every pixel, and lavapipe compiles a fragment
// shader of more than a few thousand instructions anew at every draw (measured: 30 ms a frame,
// and memory that grows by megabytes a frame, with a noise call in every pattern).

struct Texel {
    tint: vec3<f32>,
    roughness: f32,
    // The surface's height over its plane, m: grout and seams sunk, threads and grain raised
    // (the normal detail's source).
    height: f32,
    // The width of the relief's features, m: the relief is drawn where they span three pixels
    // or more, faded out where they span one (finer relief only aliases into speckle).
    relief: f32,
};

// Floor boards are 14 cm wide along x and up to 1.4 m long, their ends staggered row by row.
const BOARD_WIDTH: f32 = 0.14;
const BOARD_LENGTH: f32 = 1.4;

// Where a pattern is read: the part's own coordinates, turned so that wood's grain runs along the
// part's longest side, or a board's own for floor boards, or a line of print's for paper.
fn pattern_frame(pattern: u32, p: vec3<f32>, extent: vec3<f32>, seed: u32) -> vec3<f32> {
    switch pattern {
        case 1u: {
            if (extent.y > extent.x && extent.y >= extent.z) {
                return p.yzx;
            }
            if (extent.z > extent.x && extent.z > extent.y) {
                return p.zxy;
            }
            return p;
        }
        case 2u: {
            let row = floor(p.y / BOARD_WIDTH);
            let shift = lattice(vec3<i32>(i32(row), 0, 0), seed) * BOARD_LENGTH;
            let board = floor((p.x + shift) / BOARD_LENGTH);
            let across = fract(p.y / BOARD_WIDTH) - 0.5;
            return vec3<f32>(p.x + shift + board * 3.1, across * BOARD_WIDTH, p.z + row * 0.37);
        }
        case 9u: {
            let h = p.z / max(extent.z, 1e-3);
            return vec3<f32>(p.x, p.y, floor(h * 14.0) / 90.0);
        }
        default: {
            return p;
        }
    }
}

// The two noise frequencies of a pattern, per axis.
struct Frequencies {
    first: vec3<f32>,
    second: vec3<f32>,
};

fn frequencies(pattern: u32) -> Frequencies {
    switch pattern {
        case 1u, 2u: { return Frequencies(vec3<f32>(1.5, 6.0, 6.0), vec3<f32>(4.0, 120.0, 120.0)); }
        case 3u: { return Frequencies(vec3<f32>(60.0), vec3<f32>(1.0)); }
        case 4u: { return Frequencies(vec3<f32>(220.0), vec3<f32>(3.0)); }
        case 5u: { return Frequencies(vec3<f32>(7.0), vec3<f32>(19.0)); }
        case 6u: { return Frequencies(vec3<f32>(3.0), vec3<f32>(40.0)); }
        case 7u: { return Frequencies(vec3<f32>(30.0), vec3<f32>(1.0)); }
        case 8u: { return Frequencies(vec3<f32>(4.0, 400.0, 400.0), vec3<f32>(1.0)); }
        case 9u: { return Frequencies(vec3<f32>(90.0), vec3<f32>(1.0)); }
        case 10u: { return Frequencies(vec3<f32>(25.0), vec3<f32>(300.0)); }
        default: { return Frequencies(vec3<f32>(12.0), vec3<f32>(1.0)); }
    }
}

// Growth rings around the frame's x axis, wavy by `wobble`, with fibres.
fn rings(q: vec3<f32>, wobble: f32, fibre: f32) -> f32 {
    let r = fract(length(q.yz * 9.0 + vec2<f32>(3.7, 1.3)) * 2.2 + wobble * 2.5);
    return 1.0 - smoothstep(0.55, 0.95, r) * 0.28 - fibre * 0.1;
}

// The tint of floor boards at `p` (each board its own shade, seams darker, grain in it) and its
// height (the seams sunk 2 mm).
fn planks(p: vec3<f32>, grain: f32, seed: u32) -> vec2<f32> {
    let row = floor(p.y / BOARD_WIDTH);
    let shift = lattice(vec3<i32>(i32(row), 0, 0), seed) * BOARD_LENGTH;
    let board = floor((p.x + shift) / BOARD_LENGTH);
    let across = fract(p.y / BOARD_WIDTH);
    let along = fract((p.x + shift) / BOARD_LENGTH);
    let seam = min(min(across, 1.0 - across) * BOARD_WIDTH, min(along, 1.0 - along) * BOARD_LENGTH);
    let groove = 1.0 - 0.45 * (1.0 - smoothstep(0.0, 0.003, seam));
    let tone = 0.82 + 0.3 * lattice(vec3<i32>(i32(row), i32(board), 3), seed);
    // The boards' edges round down into the seams over 8 mm.
    return vec2<f32>(grain * tone * groove, 0.0015 * smoothstep(0.0, 0.008, seam));
}

// Square tiles of 30 or 20 cm with grout; each tile a little its own shade.
fn tiles(p: vec3<f32>, speck: f32, seed: u32) -> Texel {
    let size = select(0.3, 0.2, (seed & 1u) == 1u);
    let cell = floor(p.xy / size);
    let f = fract(p.xy / size);
    let edge = min(min(f.x, 1.0 - f.x), min(f.y, 1.0 - f.y)) * size;
    let grout = smoothstep(0.002, 0.004, edge);
    let tone = 0.92 + 0.1 * lattice(vec3<i32>(i32(cell.x), i32(cell.y), 5), seed) - 0.04 * speck;
    // The grout lies 2 mm below the tiles, whose edges round down to it over 12 mm.
    let bevel = smoothstep(0.002, 0.014, edge);
    return Texel(mix(vec3<f32>(0.55, 0.53, 0.5), vec3<f32>(tone), grout), (1.0 - grout) * 0.6, 0.002 * bevel, 0.012);
}

// A printed label band of a second colour, with lines of print around it.
fn print(p: vec3<f32>, extent: vec3<f32>, ink: f32, seed: u32, base: vec3<f32>) -> vec3<f32> {
    let h = p.z / max(extent.z, 1e-3);
    let hue = vec3<f32>(lattice(vec3<i32>(1, 2, 3), seed), lattice(vec3<i32>(4, 5, 6), seed), lattice(vec3<i32>(7, 8, 9), seed));
    let accent = hue * hue / max(base, vec3<f32>(0.05));
    let low = -0.2 + 0.3 * hue.x;
    let band = step(low, h) * step(h, low + 0.45);
    let line = step(0.55, fract(h * 14.0)) * step(0.35, ink);
    return mix(vec3<f32>(1.0), accent, band) * (1.0 - 0.5 * line * (1.0 - band));
}

fn texel(pattern: u32, p: vec3<f32>, extent: vec3<f32>, seed: u32, base: vec3<f32>) -> Texel {
    let q = pattern_frame(pattern, p, extent, seed);
    let f = frequencies(pattern);
    let a = noise(q * f.first, seed);
    let b = noise(q * f.second, seed + 7u);
    switch pattern {
        case 1u: { return Texel(vec3<f32>(rings(q, a, b)), 0.0, 0.0003 * b, 0.008); }
        case 2u: {
            let board = planks(p, rings(q, a, b), seed);
            return Texel(vec3<f32>(board.x), 0.0, board.y, 0.008);
        }
        case 3u: { return tiles(p, a, seed); }
        case 4u: { return Texel(vec3<f32>(0.78 + 0.22 * a + 0.12 * (b - 0.5)), 0.0, 0.0015 * a, 0.005); }
        case 5u: { return Texel(vec3<f32>(1.0 + 0.06 * (0.65 * a + 0.35 * b - 0.5)), 0.0, 0.0004 * (0.65 * a + 0.35 * b), 0.05); }
        case 6u: {
            // Stone with dark veins.
            let vein = 1.0 - abs(sin(p.x * 4.0 + p.y * 2.0 + a * 7.0));
            let v4 = vein * vein * vein * vein;
            return Texel(vec3<f32>(1.0 - v4 * v4 * 0.45 + 0.05 * (b - 0.5)), 0.0, 0.0, 1.0);
        }
        case 7u: {
            // Warp and weft, about 4 threads a centimetre, with slubs.
            let weave = 0.5 + 0.5 * sin(250.0 * (p.x + p.z)) * sin(250.0 * (p.y - p.z));
            return Texel(vec3<f32>(0.82 + 0.12 * weave + 0.1 * (a - 0.5)), 0.0, 0.0004 * weave, 0.0025);
        }
        case 8u: { return Texel(vec3<f32>(0.9 + 0.12 * a), 0.1 * a, 0.0001 * a, 0.0025); }
        case 9u: { return Texel(print(p, extent, a, seed, base), 0.0, 0.0, 1.0); }
        case 10u: { return Texel(vec3<f32>(0.85 + 0.3 * a - 0.25 * step(0.93, b)), 0.0, 0.0005 * a, 0.04); }
        case 11u: { return Texel(vec3<f32>(0.6), 0.0, 0.0, 1.0); }
        default: { return Texel(vec3<f32>(0.97 + 0.06 * a), 0.0, 0.0, 1.0); }
    }
}

// ---- light ----

// How much of a light reaches a world point (1: all), from one map. The maps of the sun are
// orthographic (w is 1), the lamp's in perspective; a point behind the lamp is lit.
fn sun_through(map: texture_depth_2d, matrix: mat4x4<f32>, p: vec3<f32>) -> f32 {
    let h = matrix * vec4<f32>(p, 1.0);
    let c = h.xyz / max(h.w, 1e-6);
    let uv = vec2<f32>(c.x * 0.5 + 0.5, 0.5 - c.y * 0.5);
    if (any(uv < vec2<f32>(0.0)) || any(uv > vec2<f32>(1.0)) || c.z > 1.0 || h.w <= 0.0) {
        return 1.0;
    }
    return textureSampleCompareLevel(map, shadow_sampler, uv, c.z);
}

fn sunlit(p: vec3<f32>, n: vec3<f32>) -> f32 {
    // Lifted off the surface along its normal, against acne.
    let q = p + n * 0.02;
    let fixed = select(1.0, sun_through(static_map, lights.static_shadow, q), lights.counts.y != 0u);
    let moving = select(1.0, sun_through(dynamic_map, lights.dynamic_shadow, q), lights.counts.z != 0u);
    return min(fixed, moving);
}

// How open the sky is over a point's neighbourhood (1: open; 0: covered), from the sky map:
// four lookups (each a filtered 2 × 2 comparison) at 15 to 35 cm around a centre lifted off the
// surface along its normal by the farthest one's distance, so that a wall's own footprint does
// not count against it but a table top over a floor, the boards of a shelf or the walls of a
// corner do.
fn sky_open(p: vec3<f32>, n: vec3<f32>) -> f32 {
    let centre = vec3<f32>((p + n * 0.37).xy, p.z + 0.02);
    // Four points around the centre, 35 and 15 cm off, a quarter turn apart.
    let m = lights.sky_shadow;
    let a = sun_through(sky_map, m, centre + vec3<f32>(0.322, 0.136, 0.0));
    let b = sun_through(sky_map, m, centre + vec3<f32>(-0.058, 0.138, 0.0));
    let c = sun_through(sky_map, m, centre + vec3<f32>(-0.322, -0.136, 0.0));
    let d = sun_through(sky_map, m, centre + vec3<f32>(0.058, -0.138, 0.0));
    return 0.25 * (a + b + c + d);
}

// Normal detail: the surface's height `h` (grout, seams, weave, grain) tilts the shading normal
// `n` at world point `p` by how it changes between neighbouring pixels against how `p` does —
// bump mapping without tangents (Mikkelsen's surface gradient), so any part in any pose gets it.
// Called in uniform control flow (the derivatives need the whole 2 × 2 quad).
fn bumped(n: vec3<f32>, p: vec3<f32>, h: f32) -> vec3<f32> {
    let dx = dpdx(p);
    let dy = dpdy(p);
    let r1 = cross(dy, n);
    let r2 = cross(n, dx);
    let det = dot(dx, r1);
    let grad = sign(det) * (dpdx(h) * r1 + dpdy(h) * r2);
    let b = abs(det) * n - grad;
    let len = length(b);
    return select(n, b / max(len, 1e-20), len > 1e-20);
}

// Diffuse plus a normalised Blinn-Phong lobe standing in for GGX, with Schlick's Fresnel.
fn brdf(n: vec3<f32>, l: vec3<f32>, v: vec3<f32>, albedo: vec3<f32>, roughness: f32, metallic: f32) -> vec3<f32> {
    let ndl = max(dot(n, l), 0.0);
    if (ndl <= 0.0) {
        return vec3<f32>(0.0);
    }
    let h = normalize(l + v);
    let a = max(roughness * roughness, 0.002);
    let shininess = 2.0 / (a * a) - 2.0;
    let f0 = mix(vec3<f32>(0.04), albedo, metallic);
    let vh = max(dot(v, h), 0.0);
    let m = 1.0 - vh;
    let m2 = m * m;
    let f = f0 + (vec3<f32>(1.0) - f0) * (m2 * m2 * m);
    let spec = f * ((shininess + 8.0) / 25.13) * pow(max(dot(n, h), 0.0), shininess);
    let diffuse = albedo * (1.0 - metallic) * (vec3<f32>(1.0) - f);
    return (diffuse + spec * 3.14159) * ndl;
}

// Filmic tone mapping (Narkowicz's fit of ACES).
fn aces(x: vec3<f32>) -> vec3<f32> {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), vec3<f32>(0.0), vec3<f32>(1.0));
}

// No branch or loop here depends on the lights' uniform alone: lavapipe compiles a shader anew,
// at every draw whose uniforms changed, when such a condition could be folded (its "inlined
// uniforms"); measured: 30 ms a frame and megabytes of memory a frame with a loop over the
// lamp count. So the lamps are a fixed eight (unused ones black, lighting an empty room) and
// the shadow maps' flags are selected, not branched on.
@fragment
fn fs_realistic(in: RealisticVertex) -> SurfaceOut {
    let n = seen_normal(in.normal, in.camera);
    let to_eye = normalize(-in.camera);
    let rotation = mat3x3<f32>(lights.camera_to_world[0].xyz, lights.camera_to_world[1].xyz, lights.camera_to_world[2].xyz);
    let nw = rotation * n;
    let vw = rotation * to_eye;
    let pattern = in.surface.x & 255u;
    let roughness0 = f32((in.surface.x >> 8u) & 255u) / 255.0;
    let metallic = f32((in.surface.x >> 16u) & 255u) / 255.0;
    let t = texel(pattern, in.local, in.extent, in.surface.y, in.color.rgb);
    let albedo = clamp(in.color.rgb * t.tint, vec3<f32>(0.0), vec3<f32>(1.0));
    let roughness = clamp(roughness0 + t.roughness, 0.04, 1.0);
    // The lights see the detailed normal; the normal modality, shadows and occlusion the
    // geometric one.
    let footprint = max(length(dpdx(in.world)), length(dpdy(in.world)));
    let drawn = smoothstep(1.0, 3.0, t.relief / max(footprint, 1e-6));
    let shading = bumped(nw, in.world, t.height * drawn * lights.detail.x);

    let up = 0.5 + 0.5 * nw.z;
    // Ambient occlusion: what covers the sky over the point dims its ambient light, and the
    // rooms' lamps (which hang above) as much: a soft shade under tables and in corners.
    let open = select(1.0, sky_open(in.world, nw), lights.counts.x != 0u);
    let occlusion = 0.3 + 0.7 * open;
    // Ambient light: diffuse from the sky and the ground around the normal, and the sky and
    // the ground seen mirrored in the surface — the one light a metal has besides its
    // highlights (without it a stainless oven read near black) — by Schlick's Fresnel with
    // roughness, a rough surface's mirror direction leaning to its normal (it sees them blurred).
    let nv = max(dot(shading, vw), 0.0);
    let f0 = mix(vec3<f32>(0.04), albedo, metallic);
    let g = 1.0 - nv;
    let g2 = g * g;
    let mirrored = f0 + (max(vec3<f32>(1.0 - roughness), f0) - f0) * (g2 * g2 * g);
    let mirror = normalize(mix(reflect(-vw, shading), shading, roughness * roughness));
    let around = mix(lights.ground.rgb, lights.sky.rgb, up);
    let seen = mix(lights.ground.rgb, lights.sky.rgb, 0.5 + 0.5 * mirror.z);
    var light = (albedo * (1.0 - metallic) * (vec3<f32>(1.0) - mirrored) * around + mirrored * seen) * occlusion;
    let sun = lights.sun.xyz;
    if (dot(nw, sun) > 0.0) {
        light += brdf(shading, sun, vw, albedo, roughness, metallic) * lights.sun_color.rgb * sunlit(in.world, nw);
    }
    // The first lamp is the camera's room's, the one with a shadow map.
    let lamp_lit = select(1.0, sun_through(lamp_map, lights.lamp_shadow, in.world + nw * 0.02), lights.counts.w != 0u);
    for (var k = 0u; k < 8u; k++) {
        let room = lights.lamp_room[k];
        if (in.world.x < room.x || in.world.y < room.y || in.world.x > room.z || in.world.y > room.w) {
            continue;
        }
        let to_lamp = lights.lamp_position[k].xyz - in.world;
        let d2 = dot(to_lamp, to_lamp);
        let l = to_lamp * inverseSqrt(d2);
        let shade = select(1.0, lamp_lit, k == 0u);
        light += brdf(shading, l, vw, albedo, roughness, metallic) * lights.lamp_color[k].rgb * occlusion * shade / (d2 + 0.5);
    }
    light += albedo * in.color.w * 3.0;

    return surface_out(aces(light * lights.sky.w), n, in.camera, in.ids);
}
