//! What the websocket tests share: reading the server's messages as a page does.

#![allow(dead_code)]

use behavior_web::{ServeOptions, Server};
use futures_util::{SinkExt, StreamExt};
use serde_json::Value;
use std::future::Future;
use std::net::SocketAddr;
use std::time::Duration;
use tokio::net::TcpStream;
use tokio_tungstenite::tungstenite::Message;
use tokio_tungstenite::{MaybeTlsStream, WebSocketStream};

pub type Socket = WebSocketStream<MaybeTlsStream<TcpStream>>;

/// The next text message of `kind`, skipping others (frames, statuses).
pub async fn next_of(socket: &mut Socket, kind: &str) -> Value {
    let wait = async {
        loop {
            let message = socket.next().await.expect("open").expect("readable");
            if let Message::Text(text) = message {
                let value: Value = serde_json::from_str(&text).expect("JSON from the server");
                if value["type"] == kind {
                    return value;
                }
            }
        }
    };
    tokio::time::timeout(Duration::from_secs(60), wait)
        .await
        .unwrap_or_else(|_| panic!("no `{kind}` message within 60 s"))
}

/// The next binary frame: its step and the pose of node `node`.
pub async fn next_frame(socket: &mut Socket, node: usize) -> (u32, [f32; 3]) {
    loop {
        let message = socket.next().await.expect("open").expect("readable");
        if let Message::Binary(bytes) = message {
            let step = u32::from_le_bytes(bytes[..4].try_into().unwrap());
            let at = 4 + node * 28;
            let f = |k: usize| {
                f32::from_le_bytes(bytes[at + 4 * k..at + 4 * k + 4].try_into().unwrap())
            };
            return (step, [f(0), f(1), f(2)]);
        }
    }
}

pub async fn send(socket: &mut Socket, text: &str) {
    socket.send(Message::Text(text.into())).await.unwrap();
}

/// A server bound to a free port of 127.0.0.1, and its address.
pub async fn bind_local() -> (Server, SocketAddr) {
    let options = ServeOptions {
        addr: "127.0.0.1:0".parse().unwrap(),
    };
    let server = Server::bind(&options).await.unwrap();
    let addr = server.local_addr().unwrap();
    (server, addr)
}

/// A shutdown signal for a server: send on the first to complete the second.
pub fn shutdown() -> (
    tokio::sync::oneshot::Sender<()>,
    impl Future<Output = ()> + Send + 'static,
) {
    let (stop, stopped) = tokio::sync::oneshot::channel::<()>();
    (stop, async {
        let _ = stopped.await;
    })
}
