// The world drawn from one camera. Two passes share the vertex stage:
// - `fs_surface`: lit colour, camera-frame normal + depth, instance and category ids;
// - `fs_motion`: optical flow (pixels) and scene flow (m) since the previous frame.

struct Globals {
    view_proj: mat4x4<f32>,
    prev_view_proj: mat4x4<f32>,
    // World to camera frame (x forward, y left, z up).
    view: mat4x4<f32>,
    // Toward the light, camera frame.
    light: vec4<f32>,
    // Image width and height in pixels.
    size: vec4<f32>,
};

@group(0) @binding(0) var<uniform> g: Globals;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
};

// Affine transforms as three rows; the normal matrix as three rows (w of the first: shine).
struct InstanceIn {
    @location(2) m0: vec4<f32>,
    @location(3) m1: vec4<f32>,
    @location(4) m2: vec4<f32>,
    @location(5) n0: vec4<f32>,
    @location(6) n1: vec4<f32>,
    @location(7) n2: vec4<f32>,
    @location(8) p0: vec4<f32>,
    @location(9) p1: vec4<f32>,
    @location(10) p2: vec4<f32>,
    // Linear albedo, and emission in w.
    @location(11) color: vec4<f32>,
    // Instance id, and category id | highlight << 16.
    @location(12) ids: vec2<u32>,
};

// What the surface pass interpolates: as little as it needs (a CPU rasterizer pays for every
// number per triangle), in the camera's frame so that a pixel needs no matrix.
struct SurfaceVertex {
    @builtin(position) clip: vec4<f32>,
    @location(0) camera: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) @interpolate(flat) color: vec4<f32>,
    @location(3) @interpolate(flat) ids: vec2<u32>,
    @location(4) @interpolate(flat) shine: f32,
};

// What the motion pass interpolates.
struct MotionVertex {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) prev_world: vec3<f32>,
    @location(2) prev_clip: vec4<f32>,
    @location(3) now_clip: vec4<f32>,
};

fn affine(r0: vec4<f32>, r1: vec4<f32>, r2: vec4<f32>, p: vec3<f32>) -> vec3<f32> {
    let q = vec4<f32>(p, 1.0);
    return vec3<f32>(dot(r0, q), dot(r1, q), dot(r2, q));
}

@vertex
fn vs_surface(v: VertexIn, i: InstanceIn) -> SurfaceVertex {
    var out: SurfaceVertex;
    let world = affine(i.m0, i.m1, i.m2, v.position);
    out.camera = (g.view * vec4<f32>(world, 1.0)).xyz;
    let normal = vec3<f32>(dot(i.n0.xyz, v.normal), dot(i.n1.xyz, v.normal), dot(i.n2.xyz, v.normal));
    out.normal = (g.view * vec4<f32>(normal, 0.0)).xyz;
    out.clip = g.view_proj * vec4<f32>(world, 1.0);
    out.color = i.color;
    out.ids = i.ids;
    out.shine = i.n0.w;
    return out;
}

@vertex
fn vs_motion(v: VertexIn, i: InstanceIn) -> MotionVertex {
    var out: MotionVertex;
    let world = affine(i.m0, i.m1, i.m2, v.position);
    let prev = affine(i.p0, i.p1, i.p2, v.position);
    out.world = world;
    out.prev_world = prev;
    out.clip = g.view_proj * vec4<f32>(world, 1.0);
    out.now_clip = out.clip;
    out.prev_clip = g.prev_view_proj * vec4<f32>(prev, 1.0);
    return out;
}

struct SurfaceOut {
    @location(0) color: vec4<f32>,
    @location(1) geometry: vec4<f32>,
    @location(2) ids: vec2<u32>,
};

@fragment
fn fs_surface(in: SurfaceVertex) -> SurfaceOut {
    var n = normalize(in.normal);
    let to_eye = normalize(-in.camera);
    // Two-sided: the inside of an open box is lit as its outside.
    if (dot(n, to_eye) < 0.0) {
        n = -n;
    }
    let l = g.light.xyz;
    let diffuse = max(dot(n, l), 0.0);
    let facing = max(dot(n, to_eye), 0.0);
    let half_way = normalize(l + to_eye);
    // cos^40 by squaring (x^8 · x^32): a CPU rasterizer's pow is an exp and a log per pixel.
    let c2 = max(dot(n, half_way), 0.0) * max(dot(n, half_way), 0.0);
    let c8 = (c2 * c2) * (c2 * c2);
    let c32 = (c8 * c8) * (c8 * c8);
    let specular = in.shine * c8 * c32;
    let albedo = in.color.rgb;
    let lit = albedo * (0.3 + 0.5 * diffuse + 0.2 * facing + in.color.w) + vec3<f32>(specular);
    var out: SurfaceOut;
    out.color = vec4<f32>(min(lit, vec3<f32>(1.0)), 1.0);
    out.geometry = vec4<f32>(n, in.camera.x);
    out.ids = in.ids;
    return out;
}

struct MotionOut {
    @location(0) scene: vec4<f32>,
    @location(1) flow: vec2<f32>,
};

fn to_pixel(clip: vec4<f32>) -> vec2<f32> {
    let ndc = clip.xy / clip.w;
    return vec2<f32>((ndc.x + 1.0) * 0.5 * g.size.x, (1.0 - ndc.y) * 0.5 * g.size.y);
}

@fragment
fn fs_motion(in: MotionVertex) -> MotionOut {
    var out: MotionOut;
    out.scene = vec4<f32>(in.world - in.prev_world, 0.0);
    out.flow = to_pixel(in.now_clip) - to_pixel(in.prev_clip);
    return out;
}
