//! The pages connected to a simulation thread (a live episode's or a recording's), and how
//! messages reach them: each page's task takes what is queued for it and sends it on its
//! websocket.
//!
//! Frames and statuses are superseded by the next ones, so a page that falls behind should skip
//! them rather than work through a backlog: a text message behind the backlog (a headset's rig,
//! the episode's end) would reach it late. Two limits keep the backlog short. On the server, at
//! most [`SKIPPABLE_QUEUED`] of them wait in a page's queue. In the browser, whatever the server
//! has written waits in the socket, where only the page can say how far it got: a page that
//! says how many frames it has taken (`seen`) is sent frames and statuses only while it is fewer
//! than [`FRAMES_AHEAD`] behind. Measured with the emulated headset drawing two eyes on a CPU at
//! 5 frames a second: without it, a backlog of thousands of messages, and its rig 10–20 s and the
//! episode's end 26–66 s after they were sent.

use axum::body::Bytes;
use std::collections::BTreeMap;
use tokio::sync::mpsc::Sender;
use tokio::sync::mpsc::error::TrySendError;

/// A message to a page: JSON text or a binary frame.
#[derive(Clone, Debug)]
pub(crate) enum Outgoing {
    /// Text that must arrive (a scene, an ending, a status with new particles).
    Text(String),
    /// Text the next one supersedes (a step's status: Q, metrics, checklist, every surface's
    /// colour that differs from the scene's): a slow page may skip it, as it skips frames.
    Update(String),
    /// A frame of poses (the next one supersedes it too).
    Binary(Bytes),
}

/// How many frames and updates may wait in a page's queue: a second of them at 30 steps a
/// second would be 60 (a frame and a status each step); 8 is a quarter of a second, enough to
/// ride out a page's hiccup.
pub(crate) const SKIPPABLE_QUEUED: usize = 8;

/// How many frames a page that says what it has taken may be sent beyond that.
pub(crate) const FRAMES_AHEAD: u64 = 4;

/// One page: its queue, and its frames sent and taken.
struct Page {
    tx: Sender<Outgoing>,
    /// Frames queued for it since it joined.
    sent: u64,
    /// Frames it said it has taken (none from a page that never said: no flow control).
    seen: Option<u64>,
}

impl Page {
    /// Whether a frame or an update would find the page too far behind.
    fn behind(&self) -> bool {
        let queued = self.tx.max_capacity() - self.tx.capacity();
        let room = SKIPPABLE_QUEUED.min(self.tx.max_capacity() / 2);
        let ahead = self.seen.map_or(0, |seen| self.sent.saturating_sub(seen));
        queued >= room || ahead >= FRAMES_AHEAD
    }

    fn try_send(&mut self, message: Outgoing) -> Result<(), TrySendError<Outgoing>> {
        let frame = matches!(message, Outgoing::Binary(_));
        self.tx.try_send(message)?;
        self.sent += u64::from(frame);
        Ok(())
    }
}

/// The connected pages, by client id.
#[derive(Default)]
pub(crate) struct Clients(BTreeMap<u64, Page>);

impl Clients {
    /// Admits a page, sending it `first` (what it needs to draw): it is kept only if all of it
    /// could be queued.
    pub(crate) fn join(&mut self, client: u64, tx: Sender<Outgoing>, first: Vec<Outgoing>) -> bool {
        let mut page = Page {
            tx,
            sent: 0,
            seen: None,
        };
        let sent = first.into_iter().all(|m| page.try_send(m).is_ok());
        if sent {
            self.0.insert(client, page);
        }
        sent
    }

    pub(crate) fn leave(&mut self, client: u64) {
        self.0.remove(&client);
    }

    /// A page says it has taken `frames` frames since it joined.
    pub(crate) fn seen(&mut self, client: u64, frames: u64) {
        if let Some(page) = self.0.get_mut(&client) {
            page.seen = Some(page.seen.map_or(frames, |s| s.max(frames)));
        }
    }

    /// Sends to one page; a page whose connection closed is let go.
    pub(crate) fn send_to(&mut self, client: u64, message: Outgoing) {
        if let Some(page) = self.0.get_mut(&client)
            && let Err(TrySendError::Closed(_)) = page.try_send(message)
        {
            self.0.remove(&client);
        }
    }

    /// Sends to every page. A page too far behind to take a frame or an update skips it (see
    /// the module's docs); one too slow to take a text message (a scene, an ending) is let go,
    /// as it would be wrong from then on. (Before the limits, frames, and then each step's
    /// status, filled the queue, and the ending that came next found it full: the page was let
    /// go and waited for it in vain.)
    pub(crate) fn broadcast(&mut self, message: Outgoing) {
        let must_arrive = matches!(message, Outgoing::Text(_));
        self.0.retain(|_, page| {
            if !must_arrive && page.behind() {
                return true;
            }
            match page.try_send(message.clone()) {
                Ok(()) => true,
                Err(TrySendError::Full(_)) if must_arrive => {
                    eprintln!(
                        "a page was let go: its queue of {} messages was full",
                        page.tx.max_capacity()
                    );
                    false
                }
                Err(TrySendError::Full(_)) => true,
                Err(TrySendError::Closed(_)) => false,
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A page that reads nothing: frames and statuses stop at half its queue, and an ending
    /// still fits.
    #[test]
    fn frames_leave_half_the_queue_for_what_must_arrive() {
        let (tx, mut rx) = tokio::sync::mpsc::channel(8);
        let mut clients = Clients::default();
        assert!(clients.join(1, tx, Vec::new()));
        for _ in 0..20 {
            clients.broadcast(Outgoing::Binary(Bytes::from_static(b"frame")));
            clients.broadcast(Outgoing::Update("status".into()));
        }
        for _ in 0..4 {
            clients.broadcast(Outgoing::Text("ended".into()));
        }
        assert_eq!(clients.0.len(), 1, "the page was let go");
        let mut got = Vec::new();
        while let Ok(m) = rx.try_recv() {
            got.push(matches!(m, Outgoing::Text(_)));
        }
        assert_eq!(got, [false, false, false, false, true, true, true, true]);
    }

    /// A page with a long queue that reads nothing: a few frames and statuses wait, and what
    /// must arrive comes right after them.
    #[test]
    fn a_slow_page_has_only_a_few_frames_before_what_must_arrive() {
        let (tx, mut rx) = tokio::sync::mpsc::channel(256);
        let mut clients = Clients::default();
        assert!(clients.join(1, tx, Vec::new()));
        for _ in 0..200 {
            clients.broadcast(Outgoing::Binary(Bytes::from_static(b"frame")));
            clients.broadcast(Outgoing::Update("status".into()));
        }
        clients.broadcast(Outgoing::Text("rig".into()));
        let mut got = Vec::new();
        while let Ok(m) = rx.try_recv() {
            got.push(matches!(m, Outgoing::Text(_)));
        }
        assert_eq!(got.len(), SKIPPABLE_QUEUED + 1, "{got:?}");
        assert_eq!(
            got.last(),
            Some(&true),
            "the rig comes after {SKIPPABLE_QUEUED} frames and statuses"
        );
    }

    /// A page that says what it has taken is sent frames and statuses only a few frames ahead
    /// of it; one that never says is not held back.
    #[test]
    fn a_page_that_says_what_it_took_is_kept_a_few_frames_ahead() {
        let mut clients = Clients::default();
        let (tx, mut rx) = tokio::sync::mpsc::channel(256);
        assert!(clients.join(1, tx, Vec::new()));
        let (quiet_tx, mut quiet_rx) = tokio::sync::mpsc::channel(256);
        assert!(clients.join(2, quiet_tx, Vec::new()));
        let frame = || Outgoing::Binary(Bytes::from_static(b"frame"));
        let mut taken = 0;
        for round in 0..3 {
            clients.seen(1, taken);
            for _ in 0..20 {
                clients.broadcast(frame());
                clients.broadcast(Outgoing::Update("status".into()));
            }
            let mut frames = 0;
            while let Ok(m) = rx.try_recv() {
                frames += u64::from(matches!(m, Outgoing::Binary(_)));
            }
            assert_eq!(frames, FRAMES_AHEAD, "round {round}");
            taken += frames;
            // The quiet page's queue is emptied by its task as it sends.
            while quiet_rx.try_recv().is_ok() {}
        }
        // The quiet page: its queue's limit only.
        for _ in 0..20 {
            clients.broadcast(frame());
        }
        let mut quiet = 0;
        while quiet_rx.try_recv().is_ok() {
            quiet += 1;
        }
        assert_eq!(quiet, SKIPPABLE_QUEUED);
        // A page that never drew: the ending still reaches it.
        clients.seen(1, 0);
        clients.broadcast(Outgoing::Text("ended".into()));
        assert!(matches!(rx.try_recv(), Ok(Outgoing::Text(_))));
    }
}
