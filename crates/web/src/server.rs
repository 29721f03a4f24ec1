//! The HTTP side: the embedded page at `/`, its files, and the websocket at `/ws`.
//!
//! Each websocket gets a task that parses what the client says (a bad message is answered with
//! an error and goes no further) and forwards what the simulation thread sends it. The server
//! never trusts a client with anything but the messages of `protocol.rs`.

use crate::assets::asset;
use crate::clients::Outgoing;
use crate::playback::{self, Playback};
use crate::protocol::{ClientMessage, ProtocolError, error_text};
use crate::scene::SceneFiles;
use crate::session::{self, Session, ToSim};
use axum::Router;
use axum::extract::ws::{Message, WebSocket, WebSocketUpgrade};
use axum::extract::{Query, State};
use axum::http::{HeaderMap, StatusCode, Uri, header};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use serde::Deserialize;
use std::future::Future;
use std::net::SocketAddr;
use std::path::PathBuf;
use std::pin::Pin;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc;
use std::sync::{Arc, Mutex};
use tokio::net::TcpListener;

/// Where to listen.
#[derive(Clone, Debug)]
pub struct ServeOptions {
    /// The address: 127.0.0.1 by default (`behavior serve --host` to open it to others).
    pub addr: SocketAddr,
}

/// Why the server could not run.
#[derive(Debug, thiserror::Error)]
pub enum WebError {
    /// The address could not be bound (in use, or not this machine's).
    #[error("cannot listen on {addr}: {source}")]
    Bind {
        /// The address.
        addr: SocketAddr,
        /// Why.
        source: std::io::Error,
    },
    /// The server failed while running.
    #[error("the server failed: {0}")]
    Io(#[from] std::io::Error),
    /// Teleoperation drives a robot whose two hands its 26 action numbers pose (the
    /// BehaviorRobot, the embodiment of the paper's demonstrations).
    #[error(
        "`behavior serve` drives a robot whose two hands its 26 action numbers pose (the \
         BehaviorRobot's `full` space): build the environment with it"
    )]
    NotTeleoperable,
    /// The environment has no episode (a reset failed earlier).
    #[error("the environment has no episode")]
    NoEpisode,
    /// The environment failed to reset or step.
    #[error(transparent)]
    Env(#[from] behavior_env::EnvError),
    /// A recording could not be written.
    #[error(transparent)]
    Record(#[from] behavior_env::record::RecordError),
    /// The folder for recordings could not be made.
    #[error("cannot make the recordings' folder {dir}: {source}")]
    RecordDir {
        /// The folder.
        dir: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The simulation thread stopped unexpectedly.
    #[error("the simulation thread panicked")]
    SimulationPanicked,
}

/// Largest websocket message the connection takes at all; below it, the protocol's own limit
/// answers an oversized message with an error instead of closing the connection.
const MAX_FRAME: usize = 1 << 20;

/// Messages waiting for one client before frames are skipped for it.
const CLIENT_QUEUE: usize = 256;

struct Shared {
    to_sim: Mutex<mpsc::Sender<ToSim>>,
    next_client: AtomicU64,
    /// The scenes' glTF files, published by the simulation thread.
    files: Arc<SceneFiles>,
}

impl Shared {
    fn tell(&self, message: ToSim) {
        if let Ok(tx) = self.to_sim.lock() {
            // A send fails only once the simulation has stopped; the client's socket ends soon.
            let _ = tx.send(message);
        }
    }
}

/// A server bound to its address, ready to run.
pub struct Server {
    listener: TcpListener,
}

impl Server {
    /// Binds the address.
    pub async fn bind(options: &ServeOptions) -> Result<Server, WebError> {
        let listener = TcpListener::bind(options.addr)
            .await
            .map_err(|source| WebError::Bind {
                addr: options.addr,
                source,
            })?;
        Ok(Server { listener })
    }

    /// The address bound (the port chosen when port 0 was asked for).
    pub fn local_addr(&self) -> Result<SocketAddr, WebError> {
        Ok(self.listener.local_addr()?)
    }

    /// Serves the session until `shutdown` completes; ends the running episode (keeping its
    /// recording) and returns every recording written.
    pub async fn run(
        self,
        session: Session,
        shutdown: impl Future<Output = ()> + Send + 'static,
    ) -> Result<Vec<PathBuf>, WebError> {
        self.run_with(
            move |inbox, files| session::run(session, inbox, files),
            shutdown,
        )
        .await
    }

    /// Plays the recording to every page that connects until `shutdown` completes.
    pub async fn play(
        self,
        playback: Playback,
        shutdown: impl Future<Output = ()> + Send + 'static,
    ) -> Result<(), WebError> {
        self.run_with(
            move |inbox, files| playback::run(playback, inbox, files),
            shutdown,
        )
        .await
        .map(|_| ())
    }

    /// Serves the page with `simulate` running on a thread of its own, fed the pages' messages.
    async fn run_with(
        self,
        simulate: impl FnOnce(mpsc::Receiver<ToSim>, Arc<SceneFiles>) -> Result<Vec<PathBuf>, WebError>
        + Send
        + 'static,
        shutdown: impl Future<Output = ()> + Send + 'static,
    ) -> Result<Vec<PathBuf>, WebError> {
        let (to_sim, inbox) = mpsc::channel();
        let files = Arc::new(SceneFiles::default());
        let published = files.clone();
        // The simulation failing (an episode that cannot reset, a disk full) stops the server
        // too, and `run` returns its error.
        let (failed, simulation_ended) = tokio::sync::oneshot::channel::<()>();
        let simulation = std::thread::Builder::new()
            .name("simulation".into())
            .spawn(move || {
                let result = simulate(inbox, published);
                let _ = failed.send(());
                result
            })?;
        let shared = Arc::new(Shared {
            to_sim: Mutex::new(to_sim),
            next_client: AtomicU64::new(1),
            files,
        });
        let app = Router::new()
            .route("/ws", get(websocket))
            .fallback(get(file))
            .with_state(shared.clone());
        let stop = async move {
            tokio::select! {
                () = shutdown => {}
                _ = simulation_ended => {}
            }
        };
        let served = axum::serve(self.listener, app)
            .with_graceful_shutdown(stop)
            .await;
        shared.tell(ToSim::Stop);
        let written = tokio::task::spawn_blocking(move || simulation.join())
            .await
            .map_err(|_| WebError::SimulationPanicked)?
            .map_err(|_| WebError::SimulationPanicked)??;
        served?;
        Ok(written)
    }
}

/// Serves `session` until Ctrl-C, on a runtime of its own; `ready` is told the address once it
/// listens. Returns the recordings written.
pub fn serve(
    session: Session,
    options: &ServeOptions,
    ready: impl FnOnce(SocketAddr),
) -> Result<Vec<PathBuf>, WebError> {
    until_ctrl_c(options, ready, |server, stop| server.run(session, stop))
}

/// Plays `playback` to every page that connects until Ctrl-C, on a runtime of its own; `ready`
/// is told the address once it listens.
pub fn view(
    playback: Playback,
    options: &ServeOptions,
    ready: impl FnOnce(SocketAddr),
) -> Result<(), WebError> {
    until_ctrl_c(options, ready, |server, stop| server.play(playback, stop))
}

fn until_ctrl_c<T, F: Future<Output = Result<T, WebError>>>(
    options: &ServeOptions,
    ready: impl FnOnce(SocketAddr),
    run: impl FnOnce(Server, Pin<Box<dyn Future<Output = ()> + Send>>) -> F,
) -> Result<T, WebError> {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()?;
    runtime.block_on(async {
        let server = Server::bind(options).await?;
        ready(server.local_addr()?);
        let ctrl_c = Box::pin(async {
            // Without a Ctrl-C handler the server runs until it is killed.
            if tokio::signal::ctrl_c().await.is_err() {
                std::future::pending::<()>().await;
            }
        });
        run(server, ctrl_c).await
    })
}

async fn file(uri: Uri, State(shared): State<Arc<Shared>>) -> Response {
    if let Some(scene) = shared.files.get(uri.path()) {
        return ([(header::CONTENT_TYPE, "model/gltf-binary")], scene).into_response();
    }
    match asset(uri.path()) {
        Some((mime, bytes)) => ([(header::CONTENT_TYPE, mime)], bytes).into_response(),
        // Browsers ask for an icon unprompted; there is none, and that is no error.
        None if uri.path() == "/favicon.ico" => StatusCode::NO_CONTENT.into_response(),
        None => (StatusCode::NOT_FOUND, "no such file").into_response(),
    }
}

#[derive(Deserialize)]
struct WsQuery {
    /// Present: this client only watches.
    watch: Option<String>,
}

async fn websocket(
    upgrade: WebSocketUpgrade,
    headers: HeaderMap,
    Query(query): Query<WsQuery>,
    State(shared): State<Arc<Shared>>,
) -> Response {
    if !same_origin(&headers) {
        return (
            StatusCode::FORBIDDEN,
            "the websocket admits only pages served by this server",
        )
            .into_response();
    }
    let watch = query.watch.is_some();
    upgrade
        .max_message_size(MAX_FRAME)
        .on_upgrade(move |socket| client(socket, shared, watch))
}

/// Whether a browser's websocket comes from a page of ours. Browsers send `Origin` with every
/// websocket and let any page open one to any address, so without this check a web site the
/// person visits could drive the robot through a server on 127.0.0.1. Clients that are not
/// browsers send no `Origin` and are admitted.
fn same_origin(headers: &HeaderMap) -> bool {
    let Some(origin) = headers.get(header::ORIGIN) else {
        return true;
    };
    let host = headers.get(header::HOST).and_then(|h| h.to_str().ok());
    let origin_host = origin
        .to_str()
        .ok()
        .and_then(|o| o.split_once("://"))
        .map(|(_, rest)| rest.trim_end_matches('/'));
    matches!((origin_host, host), (Some(o), Some(h)) if o.eq_ignore_ascii_case(h))
}

/// One client's connection, until it closes.
async fn client(mut socket: WebSocket, shared: Arc<Shared>, watch: bool) {
    let id = shared.next_client.fetch_add(1, Ordering::Relaxed);
    let (tx, mut rx) = tokio::sync::mpsc::channel(CLIENT_QUEUE);
    shared.tell(ToSim::Joined {
        client: id,
        watch,
        tx,
    });
    loop {
        tokio::select! {
            out = rx.recv() => {
                let Some(out) = out else { break };
                let message = match out {
                    Outgoing::Text(text) | Outgoing::Update(text) => Message::Text(text.into()),
                    Outgoing::Binary(bytes) => Message::Binary(bytes),
                };
                if socket.send(message).await.is_err() {
                    break;
                }
            }
            incoming = socket.recv() => {
                let reply = match incoming {
                    Some(Ok(Message::Text(text))) => match ClientMessage::parse(&text) {
                        Ok(message) => {
                            shared.tell(ToSim::Said { client: id, message });
                            None
                        }
                        Err(e) => Some(error_text(&e)),
                    },
                    Some(Ok(Message::Binary(_))) => Some(error_text(&ProtocolError::Binary)),
                    Some(Ok(Message::Ping(_) | Message::Pong(_))) => None,
                    Some(Ok(Message::Close(_)) | Err(_)) | None => break,
                };
                if let Some(reply) = reply
                    && socket.send(Message::Text(reply.into())).await.is_err()
                {
                    break;
                }
            }
        }
    }
    shared.tell(ToSim::Left { client: id });
}
