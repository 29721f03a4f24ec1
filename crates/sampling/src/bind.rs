//! Binding the activity's furniture and floors (the instances with an `inroom` literal) to the
//! home's own objects.
//!
//! Candidates are the home's objects of the instance's synset or a descendant standing in rooms
//! of the right type (for floors, those rooms' floors). They are drawn from the scene's
//! `objects` (furniture, doors, windows) only, never from its clutter: the books and dishes
//! lying about are no activity's objects, as in the original, where clutter is loaded after
//! sampling and left out of the activity's scope. As iGibson filters them before matching,
//! a candidate is kept only if it can host the instance's own init literals: for every object to
//! be placed on, in, under or next to the instance, a probe of that object at its smallest size
//! is placed there in a scratch copy of the home, together with its placements relative to other
//! furniture (trying their candidates too). The kept candidates are then assigned by maximum
//! bipartite matching per room type, ties broken at random so that seeds vary the choice.

use crate::error::{Literals, RuledOut, SampleError, Unsatisfied};
use crate::instantiate::Attempt;
use crate::order::target;
use crate::place::{order_relations, relation_of};
use behavior_bddl::RoomType;
use behavior_bddl::activity::{InitLiteral, InstanceId, Literal};
use behavior_bddl::taxonomy::FLOOR_SYNSET;
use behavior_sim::{ObjectId, PlacementError, Relation, World};
use pathfinding::kuhn_munkres::kuhn_munkres;
use pathfinding::matrix::Matrix;
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::Rng;
use rapier3d::math::{Pose, Vector};

/// Joint placements tried per probe when its other furniture has several candidates.
const MAX_HOST_COMBINATIONS: usize = 16;

/// An instance that an `inroom` literal asks for in a room type.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Wanted {
    instance: InstanceId,
    room: RoomType,
}

/// What the probes left of an instance's candidates.
struct Hosting {
    /// How many candidates there were.
    offered: usize,
    /// The candidates that can host every probe.
    kept: Vec<ObjectId>,
    /// Why the last rejected candidate was rejected; `None` when none was.
    rejection: Option<Rejection>,
}

/// A probe that found no place at a candidate: its literals relative to furniture, and why.
struct Rejection {
    literals: Vec<Literal>,
    cause: PlacementError,
}

/// A scratch copy of the home where probes test which furniture can host what.
struct Probing<'c> {
    world: World,
    /// The probe of each instance once made, with the spot it is parked at between tests.
    probes: Vec<Option<(ObjectId, Pose)>>,
    /// Every instance's candidates (empty for those that are not furniture).
    candidates: &'c [Vec<ObjectId>],
}

impl Attempt<'_> {
    /// Binds every instance with a positive `inroom` literal (see the module docs).
    pub(crate) fn bind_furniture(&mut self) -> Result<(), SampleError> {
        let wanted = self.wanted();
        let candidates = self.candidates(&wanted);
        if let Some(w) = wanted
            .iter()
            .find(|w| candidates[index(w.instance)].is_empty())
        {
            return Err(self.unmatched(w.instance, w.room));
        }
        let mut hosting = self.hosts(&candidates)?;
        if let Some(w) = wanted
            .iter()
            .find(|w| hosting[index(w.instance)].kept.is_empty())
        {
            return Err(self.ruled_out(w.instance, w.room, &mut hosting));
        }
        let mut rooms: Vec<RoomType> = wanted.iter().map(|w| w.room).collect();
        // By name, the order in which rooms draw from the random stream.
        rooms.sort_by_key(|r| r.name());
        rooms.dedup();
        for room in rooms {
            self.match_room(room, &wanted, &mut hosting)?;
        }
        self.home_bound = self.bindings.iter().map(Option::is_some).collect();
        Ok(())
    }

    /// The positive `inroom` literals, by instance.
    fn wanted(&self) -> Vec<Wanted> {
        let mut wanted: Vec<Wanted> = self
            .activity
            .init
            .iter()
            .filter_map(|l| match l {
                InitLiteral::InRoom {
                    instance,
                    room,
                    positive: true,
                } => Some(Wanted {
                    instance: *instance,
                    room: *room,
                }),
                _ => None,
            })
            .collect();
        wanted.sort();
        wanted
    }

    /// Whether a home object of `synset` can stand for instance `i`.
    fn fits(&self, i: InstanceId, synset: &str) -> bool {
        let want = self.synset(i);
        match (self.taxonomy.get(synset), self.taxonomy.get(want)) {
            (Some(have), Some(want)) => self.taxonomy.is_a(have, want),
            _ => synset == want,
        }
    }

    fn synset(&self, i: InstanceId) -> &str {
        &self
            .activity
            .category(self.activity.instance(i).category)
            .name
    }

    /// Each wanted instance's candidates: the room type's floors, or the objects of its kind
    /// standing in rooms of that type — furniture only, never clutter (see the module docs).
    fn candidates(&self, wanted: &[Wanted]) -> Vec<Vec<ObjectId>> {
        let scene = &self.scene;
        let mut candidates = vec![Vec::new(); self.activity.instances.len()];
        for w in wanted {
            let list: &mut Vec<ObjectId> = &mut candidates[index(w.instance)];
            for (k, r) in scene.rooms.iter().enumerate() {
                if r.kind == w.room && self.fits(w.instance, FLOOR_SYNSET) {
                    list.push(self.floors[k]);
                }
            }
            for (k, o) in scene.objects.iter().enumerate() {
                if scene.rooms[o.room].kind == w.room && self.fits(w.instance, &o.synset) {
                    list.push(self.furniture[k]);
                }
            }
        }
        candidates
    }

    /// The error for an instance the home has no (or too few) candidates for.
    fn unmatched(&self, i: InstanceId, room: RoomType) -> SampleError {
        SampleError::NoFurniture {
            scene: self.scene.name.clone(),
            instance: self.activity.instance(i).name.clone(),
            synset: self.synset(i).to_string(),
            room,
        }
    }

    /// The error for an instance left without a candidate: which literal ruled candidates out,
    /// if probes did (another attempt's probes may keep more), else that the home lacks them.
    fn ruled_out(&self, i: InstanceId, room: RoomType, hosting: &mut [Hosting]) -> SampleError {
        let hosting = &mut hosting[index(i)];
        let Some(rejection) = hosting.rejection.take() else {
            return self.unmatched(i, room);
        };
        SampleError::Literal {
            literals: Literals::of(self.activity, &rejection.literals),
            why: Unsatisfied::NotHosted(Box::new(RuledOut {
                kept: hosting.kept.len(),
                candidates: hosting.offered,
                synset: self.synset(i).to_string(),
                scene: self.scene.name.clone(),
                room,
                cause: rejection.cause,
            })),
        }
    }

    /// Assigns the wanted instances of one room type to distinct kept candidates.
    fn match_room(
        &mut self,
        room: RoomType,
        wanted: &[Wanted],
        hosting: &mut [Hosting],
    ) -> Result<(), SampleError> {
        let instances: Vec<InstanceId> = wanted
            .iter()
            .filter(|w| w.room == room)
            .map(|w| w.instance)
            .collect();
        let mut columns: Vec<ObjectId> = instances
            .iter()
            .flat_map(|&i| hosting[index(i)].kept.iter().copied())
            .collect();
        columns.sort();
        columns.dedup();
        // Which instance to blame when no full matching exists: one that lost candidates to
        // the probes, if any.
        let blame = |fallback: InstanceId, hosting: &[Hosting]| {
            instances
                .iter()
                .copied()
                .find(|&i| hosting[index(i)].kept.len() < hosting[index(i)].offered)
                .unwrap_or(fallback)
        };
        if columns.len() < instances.len() {
            let i = blame(instances[columns.len()], hosting);
            return Err(self.ruled_out(i, room, hosting));
        }
        let weights = weights(&instances, &columns, hosting, &mut self.rng);
        let (_, assignment) = kuhn_munkres(&weights);
        for (r, &c) in assignment.iter().enumerate() {
            if weights[(r, c)] < 1000 {
                let i = blame(instances[r], hosting);
                return Err(self.ruled_out(i, room, hosting));
            }
            self.bindings[index(instances[r])] = Some(columns[c]);
        }
        Ok(())
    }

    /// Which candidates of each instance can host its init literals (see the module docs).
    fn hosts(&mut self, candidates: &[Vec<ObjectId>]) -> Result<Vec<Hosting>, SampleError> {
        let mut probing: Option<Probing> = None;
        let mut out = Vec::with_capacity(candidates.len());
        for (i, list) in candidates.iter().enumerate() {
            let hosted = self.hosted_by(InstanceId(i as u32), candidates);
            if hosted.is_empty() {
                out.push(Hosting {
                    offered: list.len(),
                    kept: list.clone(),
                    rejection: None,
                });
                continue;
            }
            let probing = match &mut probing {
                Some(p) => p,
                // Without clutter: whichever candidate is bound has the clutter around it put
                // away (see `tidy`), so it is judged as it will be. Clutter is built last, so
                // the furniture's ids are the same.
                None => probing.insert(Probing {
                    world: self.scene.without_clutter().build(self.library)?.world,
                    probes: vec![None; candidates.len()],
                    candidates,
                }),
            };
            out.push(self.host_test(probing, InstanceId(i as u32), &hosted)?);
        }
        Ok(out)
    }

    /// The objects (not furniture themselves) that init literals place on, in, under or next
    /// to furniture instance `i`; none when `i` is not furniture.
    fn hosted_by(&self, i: InstanceId, candidates: &[Vec<ObjectId>]) -> Vec<InstanceId> {
        if candidates[index(i)].is_empty() {
            return Vec::new();
        }
        let mut hosted: Vec<InstanceId> = self
            .kinematic
            .iter()
            .filter(|l| l.atom.object == Some(i) && candidates[index(l.atom.subject)].is_empty())
            .map(|l| l.atom.subject)
            .collect();
        hosted.sort();
        hosted.dedup();
        hosted
    }

    /// Tests every candidate of `i` with the probes of what it hosts.
    fn host_test(
        &mut self,
        probing: &mut Probing,
        i: InstanceId,
        hosted: &[InstanceId],
    ) -> Result<Hosting, SampleError> {
        let list = &probing.candidates[index(i)];
        let mut hosting = Hosting {
            offered: list.len(),
            kept: Vec::new(),
            rejection: None,
        };
        for &candidate in list {
            match self.can_host(probing, (i, candidate), hosted)? {
                None => hosting.kept.push(candidate),
                Some(rejection) => hosting.rejection = Some(rejection),
            }
        }
        Ok(hosting)
    }

    /// Whether `candidate` can stand for `i`: `None` if every probe of what it hosts finds a
    /// place, else the first probe that does not.
    fn can_host(
        &mut self,
        probing: &mut Probing,
        (i, candidate): (InstanceId, ObjectId),
        hosted: &[InstanceId],
    ) -> Result<Option<Rejection>, SampleError> {
        for &subject in hosted {
            let (probe, parked) = self.probe(probing, subject)?;
            let literals: Vec<Literal> = self
                .kinematic
                .iter()
                .filter(|l| l.atom.subject == subject && !probing.is_free(target(l)))
                .copied()
                .collect();
            let options = probing.options(&literals, (i, candidate));
            let placed = try_options(&mut probing.world, probe, &options, &mut self.rng);
            // Back to its parking spot, out of the next probe's way.
            let _ = probing.world.bodies_mut().set_pose(probe, parked);
            if let Err(cause) = placed {
                return Ok(Some(Rejection { literals, cause }));
            }
        }
        Ok(None)
    }

    /// The probe for `subject`, made on first use: its synset's archetype at the smallest size,
    /// parked far away.
    fn probe(
        &self,
        probing: &mut Probing,
        subject: InstanceId,
    ) -> Result<(ObjectId, Pose), SampleError> {
        if let Some(probe) = probing.probes[index(subject)] {
            return Ok(probe);
        }
        let instance = self.activity.instance(subject);
        let synset = self.synset(subject);
        let archetype = self.library.resolve(synset)?;
        let size = Vector::from_array(archetype.min);
        let mut spec = self
            .library
            .instance_of(archetype, synset, &instance.name, size, 0);
        let park =
            Pose::from_translation(Vector::new(-1000.0 - 5.0 * subject.0 as f32, 1000.0, 0.0));
        spec.pose = park;
        spec.body = behavior_sim::BodyKind::Dynamic;
        let id = probing.world.add(spec).map_err(|cause| SampleError::Add {
            instance: instance.name.clone(),
            cause,
        })?;
        Ok(*probing.probes[index(subject)].insert((id, park)))
    }
}

impl Probing<'_> {
    /// Whether instance `o` is not furniture (has no candidates), so that it moves freely.
    fn is_free(&self, o: InstanceId) -> bool {
        self.candidates[index(o)].is_empty()
    }

    /// The joint placements to try for a probe by its `literals` relative to furniture: `i` at
    /// `candidate`, every other furniture at each of its candidates (up to
    /// [`MAX_HOST_COMBINATIONS`] combinations), each ordered by [`order_relations`].
    fn options(
        &self,
        literals: &[Literal],
        (i, candidate): (InstanceId, ObjectId),
    ) -> Vec<Vec<(Relation, ObjectId)>> {
        let mut options: Vec<Vec<(Relation, ObjectId)>> = vec![Vec::new()];
        for l in literals {
            let o = target(l);
            let targets = if o == i {
                &[candidate][..]
            } else {
                &self.candidates[index(o)][..]
            };
            options = options
                .iter()
                .flat_map(|prefix| {
                    targets.iter().map(move |&t| {
                        let mut v = prefix.clone();
                        v.push((relation_of(l), t));
                        v
                    })
                })
                .take(MAX_HOST_COMBINATIONS)
                .collect();
        }
        options
            .iter_mut()
            .for_each(|o| order_relations(&self.world, o));
        options
    }
}

/// The matching's weights, instances by columns: a hosting pair weighs 1000 plus a random
/// tie-breaker, so that a full matching of such pairs exists exactly when the best assignment
/// scores at least 1000 per instance, and seeds vary which one is found.
fn weights(
    instances: &[InstanceId],
    columns: &[ObjectId],
    hosting: &[Hosting],
    rng: &mut ChaCha8Rng,
) -> Matrix<i64> {
    Matrix::from_fn(instances.len(), columns.len(), |(r, c)| {
        if hosting[index(instances[r])].kept.contains(&columns[c]) {
            1000 + i64::from(rng.next_u32() % 100)
        } else {
            0
        }
    })
}

/// Places `probe` by the first of `options` that works; else the last failure. `options` is
/// never empty: every literal's furniture has at least one candidate.
fn try_options(
    world: &mut World,
    probe: ObjectId,
    options: &[Vec<(Relation, ObjectId)>],
    rng: &mut ChaCha8Rng,
) -> Result<(), PlacementError> {
    let mut last = None;
    for relations in options {
        match world.place_jointly(probe, relations, rng) {
            Ok(_) => return Ok(()),
            Err(e) => last = Some(e),
        }
    }
    Err(last.expect("at least one joint placement to try"))
}

fn index(i: InstanceId) -> usize {
    i.0 as usize
}
