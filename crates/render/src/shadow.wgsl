// Shadow maps: the sun's depth of every caster, drawn with the light's matrix.

@group(0) @binding(0) var<uniform> light: mat4x4<f32>;

@vertex
fn vs_shadow(@location(0) position: vec3<f32>) -> @builtin(position) vec4<f32> {
    return light * vec4<f32>(position, 1.0);
}
