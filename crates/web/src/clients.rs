//! The pages connected to a simulation thread (a live episode's or a recording's), and how
//! messages reach them: each page's task takes what is queued for it and sends it on its
//! websocket.

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
    Binary(Bytes),
}

/// The connected pages, by client id.
#[derive(Default)]
pub(crate) struct Clients(BTreeMap<u64, Sender<Outgoing>>);

impl Clients {
    /// Admits a page, sending it `first` (what it needs to draw): it is kept only if all of it
    /// could be queued.
    pub(crate) fn join(&mut self, client: u64, tx: Sender<Outgoing>, first: Vec<Outgoing>) -> bool {
        let sent = first.into_iter().all(|m| tx.try_send(m).is_ok());
        if sent {
            self.0.insert(client, tx);
        }
        sent
    }

    pub(crate) fn leave(&mut self, client: u64) {
        self.0.remove(&client);
    }

    /// Sends to one page; a page whose connection closed is let go.
    pub(crate) fn send_to(&mut self, client: u64, message: Outgoing) {
        if let Some(tx) = self.0.get(&client)
            && let Err(TrySendError::Closed(_)) = tx.try_send(message)
        {
            self.0.remove(&client);
        }
    }

    /// Sends to every page. A page too slow to take a frame or an update skips it; one too slow
    /// to take a text message (a scene, an ending) is let go, as it would be wrong from then on.
    /// Frames and updates fill at most half a page's queue: the other half stays free for the
    /// text messages, so a page that draws slowly (a headset emulated on a CPU) skips frames and
    /// statuses but still hears of its rig and of the episode's end. (Before, frames, and then
    /// each step's status, filled the queue, and the ending that came next found it full: the
    /// page was let go and waited for it in vain.)
    pub(crate) fn broadcast(&mut self, message: Outgoing) {
        let must_arrive = matches!(message, Outgoing::Text(_));
        self.0.retain(|_, tx| {
            if !must_arrive && 2 * tx.capacity() <= tx.max_capacity() {
                return true;
            }
            match tx.try_send(message.clone()) {
                Ok(()) => true,
                Err(TrySendError::Full(_)) if must_arrive => {
                    eprintln!(
                        "a page was let go: its queue of {} messages was full",
                        tx.max_capacity()
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
}
