//! Checkpoints: the whole world as bytes ([`World::to_bytes`]) and back ([`World::from_bytes`]),
//! so that an episode recording can hold full states and an episode resumed from one continues
//! bit-identically.
//!
//! The bytes are a 24-byte header — the magic `BHVWORLD`, the format version
//! ([`WORLD_FORMAT_VERSION`], u32 little-endian), the CRC-32 of the payload (u32 LE) and the
//! payload's length (u64 LE) — then the payload: the world's core and state systems in
//! [postcard](https://docs.rs/postcard)'s wire format (varint integers, floats as their raw
//! little-endian bits, so every float round-trips exactly). The checksum turns any accidental
//! corruption into an error before anything is decoded; a payload that passes it but does not
//! decode, or decodes into a world whose parts disagree (an object whose body is missing), is an
//! error too. Nothing in reading panics.
//!
//! What is saved and what is rebuilt is said in the crate docs.

use crate::core::Core;
use crate::states::Systems;
use crate::world::World;
use behavior_core::{Ability, AbilityParams, ParamValue};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// The first eight bytes of a saved world.
pub const WORLD_MAGIC: [u8; 8] = *b"BHVWORLD";

/// The version of the byte format [`World::to_bytes`] writes and the only one
/// [`World::from_bytes`] reads. Bump it whenever a saved type changes shape — the sim's own types
/// or rapier's (a rapier upgrade), whose layout postcard does not describe.
pub const WORLD_FORMAT_VERSION: u32 = 6;

/// Magic, version, checksum, payload length.
const HEADER_LEN: usize = 8 + 4 + 4 + 8;

/// Why bytes could not be read back as a world.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum WorldBytesError {
    /// The bytes do not start with [`WORLD_MAGIC`].
    #[error("not a saved BEHAVIOR world: the bytes do not start with the magic `BHVWORLD`")]
    NotAWorld,
    /// A world saved in another format version.
    #[error(
        "a saved world of format version {found}, but this build reads format version {expected} only"
    )]
    Version {
        /// The version in the bytes.
        found: u32,
        /// [`WORLD_FORMAT_VERSION`].
        expected: u32,
    },
    /// Fewer bytes than the header says were saved.
    #[error("truncated saved world: {len} bytes, {expected} expected")]
    Truncated {
        /// How many bytes were given.
        len: usize,
        /// How many the header (or the header itself) needs.
        expected: u64,
    },
    /// More bytes than the header says were saved.
    #[error("corrupt saved world: {extra} bytes after its end")]
    TrailingBytes {
        /// How many bytes are left over.
        extra: usize,
    },
    /// The payload's checksum does not match the header's.
    #[error(
        "corrupt saved world: checksum mismatch (stored {stored:#010x}, computed {computed:#010x})"
    )]
    Checksum {
        /// The CRC-32 in the header.
        stored: u32,
        /// The CRC-32 of the payload as given.
        computed: u32,
    },
    /// The payload does not decode as a world.
    #[error("corrupt saved world: {0}")]
    Decode(String),
    /// The payload decodes, but its parts disagree.
    #[error("inconsistent saved world: {0}")]
    Inconsistent(String),
}

/// What the payload holds, borrowed for writing.
#[derive(Serialize)]
struct SavedRef<'a> {
    core: &'a Core,
    systems: &'a Systems,
}

/// What the payload holds, owned for reading.
#[derive(Deserialize)]
struct Saved {
    core: Core,
    systems: Systems,
}

impl World {
    /// The whole state as bytes: everything [`World::snapshot`] keeps (see the crate docs), so
    /// [`World::from_bytes`] gives a world that continues bit-identically, and saving that world
    /// again gives the same bytes.
    ///
    /// Layout: a 24-byte header — [`WORLD_MAGIC`], [`WORLD_FORMAT_VERSION`] (u32 little-endian),
    /// the CRC-32 of the payload (u32 LE), the payload's length (u64 LE) — then the payload, the
    /// world in postcard's wire format (floats as their raw bits).
    ///
    /// ```
    /// use behavior_sim::{ObjectSpec, Part, Primitive, World};
    /// use rapier3d::math::Vector;
    ///
    /// let mut world = World::default();
    /// let ball = Primitive::Sphere { radius: 0.04 };
    /// world.add(ObjectSpec::new("ball_1", "ball.n.01", vec![Part::new(ball)]).at(Vector::new(0.0, 0.0, 1.0))).unwrap();
    /// world.step();
    /// let bytes = world.to_bytes();
    /// let mut resumed = World::from_bytes(&bytes).unwrap();
    /// world.step();
    /// resumed.step();
    /// assert_eq!(world.bodies().motion_bits(), resumed.bodies().motion_bits());
    /// ```
    pub fn to_bytes(&self) -> Vec<u8> {
        let saved = SavedRef {
            core: &self.core,
            systems: &self.systems,
        };
        let mut bytes = postcard::to_extend(&saved, vec![0; HEADER_LEN])
            // Every saved type writes sequences and maps of known length, which is all postcard
            // needs: a failure here is a bug in a Serialize impl, found by the tests.
            .expect("every part of a world serializes with postcard");
        let payload_len = (bytes.len() - HEADER_LEN) as u64;
        let crc = crc32fast::hash(&bytes[HEADER_LEN..]);
        bytes[..8].copy_from_slice(&WORLD_MAGIC);
        bytes[8..12].copy_from_slice(&WORLD_FORMAT_VERSION.to_le_bytes());
        bytes[12..16].copy_from_slice(&crc.to_le_bytes());
        bytes[16..24].copy_from_slice(&payload_len.to_le_bytes());
        bytes
    }

    /// A world from bytes [`World::to_bytes`] wrote, in this format version. Bytes of another
    /// version, truncated, corrupt or inconsistent ones are an error, never a panic.
    pub fn from_bytes(bytes: &[u8]) -> Result<World, WorldBytesError> {
        let payload = check_header(bytes)?;
        let (saved, rest): (Saved, &[u8]) = postcard::take_from_bytes(payload)
            .map_err(|e| WorldBytesError::Decode(e.to_string()))?;
        if !rest.is_empty() {
            return Err(WorldBytesError::Decode(format!(
                "{} payload bytes left over after the world",
                rest.len()
            )));
        }
        let world = World {
            core: saved.core,
            systems: saved.systems,
        };
        world.check_consistency()?;
        Ok(world)
    }

    /// The checks that keep a decoded world from panicking later: every per-object table has an
    /// entry per object, and every handle an object or a system names is in the physics.
    fn check_consistency(&self) -> Result<(), WorldBytesError> {
        let n = self.core.bodies.objects.len();
        self.core
            .check_consistency()
            .and_then(|()| self.systems.check_consistency(n, &self.core))
            .map_err(WorldBytesError::Inconsistent)
    }
}

/// The payload, after checking the magic, version, length and checksum.
fn check_header(bytes: &[u8]) -> Result<&[u8], WorldBytesError> {
    if bytes.len() < 8 || bytes[..8] != WORLD_MAGIC {
        // Too short to hold the magic: whatever it is, it is not a world (or all but nothing of
        // one), and the magic's absence is what to tell.
        return Err(if WORLD_MAGIC.starts_with(bytes) && !bytes.is_empty() {
            WorldBytesError::Truncated {
                len: bytes.len(),
                expected: HEADER_LEN as u64,
            }
        } else {
            WorldBytesError::NotAWorld
        });
    }
    if bytes.len() < 12 {
        return Err(WorldBytesError::Truncated {
            len: bytes.len(),
            expected: HEADER_LEN as u64,
        });
    }
    let word = |at: usize| u32::from_le_bytes(bytes[at..at + 4].try_into().expect("4 bytes"));
    let version = word(8);
    if version != WORLD_FORMAT_VERSION {
        return Err(WorldBytesError::Version {
            found: version,
            expected: WORLD_FORMAT_VERSION,
        });
    }
    if bytes.len() < HEADER_LEN {
        return Err(WorldBytesError::Truncated {
            len: bytes.len(),
            expected: HEADER_LEN as u64,
        });
    }
    let stored = word(12);
    let payload_len = u64::from_le_bytes(bytes[16..24].try_into().expect("8 bytes"));
    let available = (bytes.len() - HEADER_LEN) as u64;
    if available < payload_len {
        return Err(WorldBytesError::Truncated {
            len: bytes.len(),
            expected: HEADER_LEN as u64 + payload_len,
        });
    }
    if available > payload_len {
        return Err(WorldBytesError::TrailingBytes {
            extra: (available - payload_len) as usize,
        });
    }
    let payload = &bytes[HEADER_LEN..];
    let computed = crc32fast::hash(payload);
    if computed != stored {
        return Err(WorldBytesError::Checksum { stored, computed });
    }
    Ok(payload)
}

/// Serde for an object's abilities. [`ParamValue`] is untagged (the taxonomy's JSON writes bare
/// numbers and booleans), which only self-describing formats can read back, so the parameters
/// are written as a tagged enum.
pub(crate) mod abilities {
    use super::*;
    use serde::{Deserializer, Serializer};

    #[derive(Serialize, Deserialize)]
    enum Param {
        Bool(bool),
        Number(f64),
    }

    impl From<ParamValue> for Param {
        fn from(value: ParamValue) -> Param {
            match value {
                ParamValue::Bool(b) => Param::Bool(b),
                ParamValue::Number(x) => Param::Number(x),
            }
        }
    }

    impl From<Param> for ParamValue {
        fn from(value: Param) -> ParamValue {
            match value {
                Param::Bool(b) => ParamValue::Bool(b),
                Param::Number(x) => ParamValue::Number(x),
            }
        }
    }

    struct Params<'a>(&'a AbilityParams);

    impl Serialize for Params<'_> {
        fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            s.collect_map(self.0.iter().map(|(k, &v)| (k, Param::from(v))))
        }
    }

    pub(crate) fn serialize<S: Serializer>(
        abilities: &BTreeMap<Ability, AbilityParams>,
        s: S,
    ) -> Result<S::Ok, S::Error> {
        s.collect_map(abilities.iter().map(|(a, p)| (a, Params(p))))
    }

    pub(crate) fn deserialize<'de, D: Deserializer<'de>>(
        d: D,
    ) -> Result<BTreeMap<Ability, AbilityParams>, D::Error> {
        let raw = BTreeMap::<Ability, BTreeMap<String, Param>>::deserialize(d)?;
        Ok(raw
            .into_iter()
            .map(|(a, p)| (a, p.into_iter().map(|(k, v)| (k, v.into())).collect()))
            .collect())
    }
}
