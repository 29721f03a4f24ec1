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
    // Toward the sun.
    sun: vec4<f32>,
    sun_color: vec4<f32>,
    // Ambient from above; w: exposure.
    sky: vec4<f32>,
    ground: vec4<f32>,
    // Lamps; whether the static and the dynamic map hold anything.
    counts: vec4<u32>,
    lamp_position: array<vec4<f32>, 8>,
    lamp_color: array<vec4<f32>, 8>,
    // The footprint each lamp lights: min x, min y, max x, max y.
    lamp_room: array<vec4<f32>, 8>,
};

@group(1) @binding(0) var<uniform> lights: Lights;
@group(1) @binding(1) var static_map: texture_depth_2d;
@group(1) @binding(2) var dynamic_map: texture_depth_2d;
@group(1) @binding(3) var shadow_sampler: sampler_comparison;

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
    let world = vec4<f32>(v.position, 1.0);
    out.camera = (g.view * world).xyz;
    out.normal = (g.view * vec4<f32>(v.normal, 0.0)).xyz;
    out.clip = g.view_proj * world;
    out.color = v.color;
    out.ids = v.ids;
    out.world = v.position;
    out.local = v.local;
    out.extent = v.extent;
    out.surface = v.surface;
    return out;
}

struct SurfaceOut {
    @location(0) color: vec4<f32>,
    @location(1) geometry: vec4<f32>,
    @location(2) depth: f32,
    @location(3) ids: vec2<u32>,
};

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

// Smooth value noise in [0, 1].
fn noise(p: vec3<f32>, seed: u32) -> f32 {
    let i = vec3<i32>(floor(p));
    let f = fract(p);
    let u = f * f * (3.0 - 2.0 * f);
    let x00 = mix(lattice(i, seed), lattice(i + vec3<i32>(1, 0, 0), seed), u.x);
    let x10 = mix(lattice(i + vec3<i32>(0, 1, 0), seed), lattice(i + vec3<i32>(1, 1, 0), seed), u.x);
    let x01 = mix(lattice(i + vec3<i32>(0, 0, 1), seed), lattice(i + vec3<i32>(1, 0, 1), seed), u.x);
    let x11 = mix(lattice(i + vec3<i32>(0, 1, 1), seed), lattice(i + vec3<i32>(1, 1, 1), seed), u.x);
    return mix(mix(x00, x10, u.y), mix(x01, x11, u.y), u.z);
}

// Two octaves.
fn fbm(p: vec3<f32>, seed: u32) -> f32 {
    return 0.65 * noise(p, seed) + 0.35 * noise(p * 2.7 + vec3<f32>(3.1, 1.7, 5.3), seed + 1u);
}

// ---- patterns: each gives the albedo's tint and a roughness change ----

struct Texel {
    tint: vec3<f32>,
    roughness: f32,
};

// Growth rings around an axis along the part's longest side, wavy fibres.
fn wood(p: vec3<f32>, extent: vec3<f32>, seed: u32) -> Texel {
    var q = p;
    if (extent.y > extent.x && extent.y >= extent.z) {
        q = p.yzx;
    } else if (extent.z > extent.x && extent.z > extent.y) {
        q = p.zxy;
    }
    let wobble = fbm(q * vec3<f32>(1.5, 6.0, 6.0), seed);
    let rings = fract(length(q.yz * vec2<f32>(9.0, 9.0) + vec2<f32>(3.7, 1.3)) * 2.2 + wobble * 2.5);
    let fibre = noise(q * vec3<f32>(4.0, 120.0, 120.0), seed + 7u);
    let dark = smoothstep(0.55, 0.95, rings) * 0.28 + fibre * 0.1;
    return Texel(vec3<f32>(1.0 - dark), 0.0);
}

// Boards 14 cm wide along x, up to 1.4 m long, ends staggered row by row.
fn planks(p: vec3<f32>, seed: u32) -> Texel {
    let width = 0.14;
    let row = floor(p.y / width);
    let shift = lattice(vec3<i32>(i32(row), 0, 0), seed) * 1.4;
    let board = floor((p.x + shift) / 1.4);
    let across = fract(p.y / width);
    let along = fract((p.x + shift) / 1.4);
    let seam = min(min(across, 1.0 - across) * width, min(along, 1.0 - along) * 1.4);
    let groove = 1.0 - 0.45 * (1.0 - smoothstep(0.0, 0.003, seam));
    let tone = 0.82 + 0.3 * lattice(vec3<i32>(i32(row), i32(board), 3), seed);
    let grain = wood(vec3<f32>(p.x + shift + board * 3.1, (across - 0.5) * width, p.z + row * 0.37), vec3<f32>(1.0, 0.1, 0.01), seed);
    return Texel(grain.tint * tone * groove, 0.0);
}

// Square tiles with grout; each tile slightly its own shade.
fn tiles(p: vec3<f32>, seed: u32) -> Texel {
    let size = select(0.3, 0.2, (seed & 1u) == 1u);
    let cell = floor(p.xy / size);
    let f = fract(p.xy / size);
    let edge = min(min(f.x, 1.0 - f.x), min(f.y, 1.0 - f.y)) * size;
    let grout = smoothstep(0.002, 0.004, edge);
    let tone = 0.92 + 0.1 * lattice(vec3<i32>(i32(cell.x), i32(cell.y), 5), seed);
    let speck = 0.04 * noise(p * 60.0, seed);
    let tint = mix(vec3<f32>(0.55, 0.53, 0.5), vec3<f32>(tone - speck), grout);
    return Texel(tint, (1.0 - grout) * 0.6);
}

fn carpet(p: vec3<f32>, seed: u32) -> Texel {
    let pile = noise(p * 220.0, seed);
    let cloud = fbm(p * 3.0, seed + 3u);
    return Texel(vec3<f32>(0.78 + 0.22 * pile + 0.12 * (cloud - 0.5)), 0.0);
}

fn plaster(p: vec3<f32>, seed: u32) -> Texel {
    let n = fbm(p * 7.0, seed) - 0.5;
    return Texel(vec3<f32>(1.0 + 0.06 * n), 0.0);
}

// Stone with dark veins.
fn marble(p: vec3<f32>, seed: u32) -> Texel {
    let turbulence = fbm(p * 3.0, seed) * 7.0;
    let vein = 1.0 - abs(sin(p.x * 4.0 + p.y * 2.0 + turbulence));
    let v8 = vein * vein * vein * vein;
    let darkness = v8 * v8 * 0.45;
    return Texel(vec3<f32>(1.0 - darkness + 0.05 * (noise(p * 40.0, seed) - 0.5)), 0.0);
}

// Warp and weft, about 4 threads a centimetre.
fn fabric(p: vec3<f32>, seed: u32) -> Texel {
    let k = 250.0;
    let warp = sin(k * (p.x + p.z));
    let weft = sin(k * (p.y - p.z));
    let weave = 0.5 + 0.5 * warp * weft;
    let slub = noise(p * 30.0, seed);
    return Texel(vec3<f32>(0.82 + 0.12 * weave + 0.1 * (slub - 0.5)), 0.0);
}

// Fine streaks along x.
fn brushed(p: vec3<f32>, seed: u32) -> Texel {
    let streak = noise(p * vec3<f32>(4.0, 400.0, 400.0), seed);
    return Texel(vec3<f32>(0.9 + 0.12 * streak), 0.1 * streak);
}

// A printed label band of a second colour, with lines of print on it.
fn print(p: vec3<f32>, extent: vec3<f32>, seed: u32, base: vec3<f32>) -> Texel {
    let h = p / max(extent, vec3<f32>(1e-3));
    let hue = vec3<f32>(lattice(vec3<i32>(1, 2, 3), seed), lattice(vec3<i32>(4, 5, 6), seed), lattice(vec3<i32>(7, 8, 9), seed));
    let accent = hue * hue / max(base, vec3<f32>(0.05));
    let low = -0.2 + 0.3 * lattice(vec3<i32>(2, 2, 2), seed);
    let band = step(low, h.z) * step(h.z, low + 0.45);
    let line = step(0.55, fract(h.z * 14.0)) * step(0.35, noise(vec3<f32>(p.x * 90.0, p.y * 90.0, floor(h.z * 14.0)), seed));
    let tint = mix(vec3<f32>(1.0), accent, band) * (1.0 - 0.5 * line * (1.0 - band));
    return Texel(tint, 0.0);
}

// Mottled skin with small speckles.
fn skin(p: vec3<f32>, seed: u32) -> Texel {
    let blotch = fbm(p * 25.0, seed);
    let speck = step(0.93, noise(p * 300.0, seed + 5u));
    return Texel(vec3<f32>(0.85 + 0.3 * blotch - 0.25 * speck), 0.0);
}

fn plain(p: vec3<f32>, seed: u32) -> Texel {
    return Texel(vec3<f32>(0.97 + 0.06 * noise(p * 12.0, seed)), 0.0);
}

fn texel(pattern: u32, p: vec3<f32>, extent: vec3<f32>, seed: u32, base: vec3<f32>) -> Texel {
    switch pattern {
        case 1u: { return wood(p, extent, seed); }
        case 2u: { return planks(p, seed); }
        case 3u: { return tiles(p, seed); }
        case 4u: { return carpet(p, seed); }
        case 5u: { return plaster(p, seed); }
        case 6u: { return marble(p, seed); }
        case 7u: { return fabric(p, seed); }
        case 8u: { return brushed(p, seed); }
        case 9u: { return print(p, extent, seed, base); }
        case 10u: { return skin(p, seed); }
        case 11u: { return Texel(vec3<f32>(0.6), 0.0); }
        default: { return plain(p, seed); }
    }
}

// ---- light ----

// How much of the sun reaches a world point (1: all), from one map.
fn sun_through(map: texture_depth_2d, matrix: mat4x4<f32>, p: vec3<f32>) -> f32 {
    let c = matrix * vec4<f32>(p, 1.0);
    let uv = vec2<f32>(c.x * 0.5 + 0.5, 0.5 - c.y * 0.5);
    if (any(uv < vec2<f32>(0.0)) || any(uv > vec2<f32>(1.0)) || c.z > 1.0) {
        return 1.0;
    }
    return textureSampleCompareLevel(map, shadow_sampler, uv, c.z);
}

fn sunlit(p: vec3<f32>, n: vec3<f32>) -> f32 {
    // Lifted off the surface along its normal, against acne.
    let q = p + n * 0.02;
    var lit = 1.0;
    if (lights.counts.y != 0u) {
        lit = min(lit, sun_through(static_map, lights.static_shadow, q));
    }
    if (lights.counts.z != 0u) {
        lit = min(lit, sun_through(dynamic_map, lights.dynamic_shadow, q));
    }
    return lit;
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

@fragment
fn fs_realistic(in: RealisticVertex) -> SurfaceOut {
    // As `fs_surface`: the same normal, depth and ids.
    var n = normalize(in.normal);
    let to_eye = normalize(-in.camera);
    if (dot(n, to_eye) < 0.0) {
        n = -n;
    }
    let rotation = mat3x3<f32>(lights.camera_to_world[0].xyz, lights.camera_to_world[1].xyz, lights.camera_to_world[2].xyz);
    let nw = rotation * n;
    let vw = rotation * to_eye;
    let pattern = in.surface.x & 255u;
    let roughness0 = f32((in.surface.x >> 8u) & 255u) / 255.0;
    let metallic = f32((in.surface.x >> 16u) & 255u) / 255.0;
    let t = texel(pattern, in.local, in.extent, in.surface.y, in.color.rgb);
    let albedo = clamp(in.color.rgb * t.tint, vec3<f32>(0.0), vec3<f32>(1.0));
    let roughness = clamp(roughness0 + t.roughness, 0.04, 1.0);

    let up = 0.5 + 0.5 * nw.z;
    var light = albedo * (1.0 - 0.6 * metallic) * mix(lights.ground.rgb, lights.sky.rgb, up);
    let sun = lights.sun.xyz;
    if (dot(nw, sun) > 0.0) {
        light += brdf(nw, sun, vw, albedo, roughness, metallic) * lights.sun_color.rgb * sunlit(in.world, nw);
    }
    for (var k = 0u; k < lights.counts.x; k++) {
        let room = lights.lamp_room[k];
        if (in.world.x < room.x || in.world.y < room.y || in.world.x > room.z || in.world.y > room.w) {
            continue;
        }
        let to_lamp = lights.lamp_position[k].xyz - in.world;
        let d2 = dot(to_lamp, to_lamp);
        let l = to_lamp * inverseSqrt(d2);
        light += brdf(nw, l, vw, albedo, roughness, metallic) * lights.lamp_color[k].rgb / (d2 + 0.5);
    }
    light += albedo * in.color.w * 3.0;

    var out: SurfaceOut;
    out.color = vec4<f32>(aces(light * lights.sky.w), 1.0);
    out.geometry = vec4<f32>(n, in.camera.x);
    out.depth = in.camera.x;
    out.ids = in.ids;
    return out;
}
