// What both profiles' shaders share: the frame's globals and the vertex as the CPU places it
// (`frame_geometry.rs`).

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

// A vertex placed in the world by the CPU (see `frame_geometry.rs`).
struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    // Where this point was last frame.
    @location(2) previous: vec3<f32>,
    @location(3) shine: f32,
    // Linear albedo, and emission in w.
    @location(4) color: vec4<f32>,
    // Instance id, and category id | highlight << 16.
    @location(5) ids: vec2<u32>,
    // Where the point is in its part's own frame, m (the realistic profile's patterns).
    @location(6) local: vec3<f32>,
    // The part's half size, m.
    @location(7) extent: vec3<f32>,
    // Pattern, roughness and metallic (a byte each), and the object's seed.
    @location(8) surface: vec2<u32>,
};


// Where a vertex lands: its clip position, and its position and normal in the camera's frame.
// Both profiles' surface passes place vertices with this one function and finish pixels with
// `surface_out`, so their depth, normals and ids are the same bit for bit.
struct Placed {
    clip: vec4<f32>,
    camera: vec3<f32>,
    normal: vec3<f32>,
};

fn place(v: VertexIn) -> Placed {
    let world = vec4<f32>(v.position, 1.0);
    return Placed(g.view_proj * world, (g.view * world).xyz, (g.view * vec4<f32>(v.normal, 0.0)).xyz);
}

struct SurfaceOut {
    @location(0) color: vec4<f32>,
    @location(1) geometry: vec4<f32>,
    @location(2) depth: f32,
    @location(3) ids: vec2<u32>,
};

// The unit normal on the side the eye sees (two-sided: the inside of an open box is lit as its
// outside), camera frame.
fn seen_normal(normal: vec3<f32>, camera: vec3<f32>) -> vec3<f32> {
    let n = normalize(normal);
    return select(n, -n, dot(n, normalize(-camera)) < 0.0);
}

fn surface_out(color: vec3<f32>, n: vec3<f32>, camera: vec3<f32>, ids: vec2<u32>) -> SurfaceOut {
    var out: SurfaceOut;
    out.color = vec4<f32>(color, 1.0);
    out.geometry = vec4<f32>(n, camera.x);
    out.depth = camera.x;
    out.ids = ids;
    return out;
}
