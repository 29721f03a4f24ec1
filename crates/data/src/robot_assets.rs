//! Robots' real meshes from the MIT-licensed PyPI package `gymnasium-robotics==1.4.2`: its
//! `gymnasium_robotics/envs/assets` folder holds Fetch's MuJoCo model (`fetch/robot.xml`,
//! `fetch/shared.xml`, adapted by OpenAI from Fetch Robotics' BSD-licensed `fetch_description`)
//! and its meshes (`stls/fetch/*.stl`), with the folder's `LICENSE.md` naming their origin.
//!
//! Where they come from, in order:
//! 1. the `BEHAVIOR_ROBOT_ASSETS` environment variable: that folder, or `none` to do without
//!    (robots then keep their procedural look);
//! 2. the cache `$XDG_CACHE_HOME/behavior/gymnasium-robotics-1.4.2`, filled on first use from the
//!    sdist with pip (26 MB downloaded; the Fetch files kept, 2 MB).

use crate::DataError;
use crate::fetch::Package;
use std::path::{Path, PathBuf};

/// The environment variable naming the assets folder, or `none`.
pub const ROBOT_ASSETS_ENV_VAR: &str = "BEHAVIOR_ROBOT_ASSETS";
pub(crate) const VERSION: &str = "1.4.2";

const GYMNASIUM_ROBOTICS: Package = Package {
    name: "gymnasium-robotics",
    version: VERSION,
    folder: "gymnasium_robotics/envs/assets",
    keep: &["fetch", "stls/fetch", "LICENSE.md"],
    marker: "fetch/robot.xml",
    by_hand: "point BEHAVIOR_ROBOT_ASSETS at its `gymnasium_robotics/envs/assets` folder (or set it to `none` to draw robots from their own shapes)",
};

/// The files every assets folder must have.
const NEEDED: [&str; 3] = [
    "fetch/robot.xml",
    "fetch/shared.xml",
    "stls/fetch/base_link_collision.stl",
];

/// A located assets folder (gymnasium-robotics' `envs/assets`).
#[derive(Clone, Debug)]
pub struct RobotAssets {
    root: PathBuf,
}

impl RobotAssets {
    /// Finds the assets: `BEHAVIOR_ROBOT_ASSETS`, else the cache, fetching if needed. `Ok(None)`
    /// where the variable says `none`. `progress` receives one line before a fetch starts.
    pub fn locate(progress: impl FnOnce(&str)) -> Result<Option<RobotAssets>, DataError> {
        match std::env::var_os(ROBOT_ASSETS_ENV_VAR).filter(|p| !p.is_empty()) {
            Some(value) if value == "none" => Ok(None),
            Some(path) => RobotAssets::open(Path::new(&path)).map(Some),
            None => RobotAssets::open(&GYMNASIUM_ROBOTICS.cached(progress)?).map(Some),
        }
    }

    /// Uses `path` as the assets folder, checking that it has the expected files.
    pub fn open(path: &Path) -> Result<RobotAssets, DataError> {
        match NEEDED.iter().find(|f| !path.join(f).is_file()) {
            Some(missing) => Err(DataError::NotRobotAssets {
                path: path.to_path_buf(),
                missing: missing.to_string(),
            }),
            None => Ok(RobotAssets {
                root: path.to_path_buf(),
            }),
        }
    }

    /// The folder (`gymnasium_robotics/envs/assets`).
    pub fn root(&self) -> &Path {
        &self.root
    }

    /// Fetch's MuJoCo model: the robot's bodies and geoms (`fetch/robot.xml`).
    pub fn fetch_model(&self) -> PathBuf {
        self.root.join("fetch/robot.xml")
    }

    /// The definitions it uses: meshes' files, materials, geom classes (`fetch/shared.xml`).
    pub fn fetch_definitions(&self) -> PathBuf {
        self.root.join("fetch/shared.xml")
    }

    /// The folder of Fetch's STL meshes (`stls/fetch`).
    pub fn fetch_meshes(&self) -> PathBuf {
        self.root.join("stls/fetch")
    }
}
