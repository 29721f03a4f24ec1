//! The page's files, embedded at build time (see `build.rs`): ours and three.js's.

/// (URL path, MIME type, contents) of every file the page loads.
const ASSETS: &[(&str, &str, &[u8])] = include!(concat!(env!("OUT_DIR"), "/assets.rs"));

/// The file served at `path` (`/` is the page), with its MIME type.
pub(crate) fn asset(path: &str) -> Option<(&'static str, &'static [u8])> {
    let path = if path == "/" { "/index.html" } else { path };
    ASSETS
        .iter()
        .find(|(p, _, _)| *p == path)
        .map(|&(_, mime, bytes)| (mime, bytes))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_page_and_three_js_are_embedded() {
        let (mime, page) = asset("/").expect("the page");
        assert!(mime.starts_with("text/html"));
        let page = std::str::from_utf8(page).expect("UTF-8");
        assert!(page.contains("importmap") && page.contains("/three/three.module.js"));
        let (_, three) = asset("/three/three.module.js").expect("three.js");
        assert!(
            three.len() > 100_000,
            "three.module.js is {} bytes",
            three.len()
        );
        assert!(asset("/three/addons/controls/OrbitControls.js").is_some());
        assert!(asset("/../Cargo.toml").is_none());
    }
}
