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
    Text(String),
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

    /// Sends to every page. A page too slow to take a frame skips it; one too slow to take a
    /// text message (a scene, an ending) is let go, as it would be wrong from then on.
    pub(crate) fn broadcast(&mut self, message: Outgoing) {
        let must_arrive = matches!(message, Outgoing::Text(_));
        self.0.retain(|_, tx| match tx.try_send(message.clone()) {
            Ok(()) => true,
            Err(TrySendError::Full(_)) => !must_arrive,
            Err(TrySendError::Closed(_)) => false,
        });
    }
}
