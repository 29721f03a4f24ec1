//! Without a Vulkan driver the renderer says which packages to install. Alone in its test binary:
//! it points the Vulkan loader at a driver list that does not exist, before anything else runs.

use behavior_render::{RenderError, Renderer};

#[test]
fn a_missing_vulkan_driver_names_the_packages_to_install() {
    // SAFETY: this binary's only test sets these before any other thread reads the environment.
    unsafe {
        std::env::set_var("VK_ICD_FILENAMES", "/nonexistent/behavior-no-driver.json");
        std::env::set_var("VK_DRIVER_FILES", "/nonexistent/behavior-no-driver.json");
    }
    let err = match Renderer::new() {
        Ok(r) => panic!("an adapter without a driver: {}", r.adapter()),
        Err(e) => e,
    };
    assert!(matches!(err, RenderError::NoAdapter { .. }), "{err:?}");
    let message = err.to_string();
    assert!(
        message.contains("mesa-vulkan-drivers libvulkan1"),
        "{message}"
    );
}
