// The world drawn from one camera, in two passes:
// - `fs_surface`: lit colour, camera-frame normal with depth (or depth alone), instance and
//   category ids;
// - `fs_motion`: scene flow (m) and optical flow (pixels) since the previous frame.
// A pipeline gives targets only to the outputs the modalities asked for need (`pipeline.rs`).

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

@vertex
fn vs_surface(v: VertexIn) -> SurfaceVertex {
    var out: SurfaceVertex;
    let placed = place(v);
    out.clip = placed.clip;
    out.camera = placed.camera;
    out.normal = placed.normal;
    out.color = v.color;
    out.ids = v.ids;
    out.shine = v.shine;
    return out;
}

@vertex
fn vs_motion(v: VertexIn) -> MotionVertex {
    var out: MotionVertex;
    out.world = v.position;
    out.prev_world = v.previous;
    out.clip = g.view_proj * vec4<f32>(v.position, 1.0);
    out.now_clip = out.clip;
    out.prev_clip = g.prev_view_proj * vec4<f32>(v.previous, 1.0);
    return out;
}

@fragment
fn fs_surface(in: SurfaceVertex) -> SurfaceOut {
    let n = seen_normal(in.normal, in.camera);
    let to_eye = normalize(-in.camera);
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
    return surface_out(min(lit, vec3<f32>(1.0)), n, in.camera, in.ids);
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
