// The coindie review app. The server owns the state (the replayed edit log, coindie.clustering.corrections);
// this page draws it: the link overrides come resolved from /api/state, and the slider only recomputes the
// connected components of the kept links (value > t and not cut, or forced) to recolour the graph. The links
// are the probabilities (the paper's τ), or, for a project opened as `coindie cluster --auto` cuts it, the
// merges of each side's tree (state.links, valued so that every side's own cut is at the start value).
import Graph from "graphology";
import Sigma from "sigma";
import { threeView } from "./three_view.js";

const params = new URLSearchParams(location.search);
const TOKEN = params.get("token") || "";
const CLIENT = "tab-" + Math.random().toString(36).slice(2, 10);
const PALETTE = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#17becf",
  "#bcbd22", "#393b79", "#637939", "#8c6d31", "#843c39", "#7b4173", "#3182bd", "#e6550d", "#31a354",
  "#756bb1", "#636363", "#ad494a"];
const SINGLETON = "#b9b2a6";
const NEIGHBOURS = 24; // rows of the coin panel (each with a server-rendered thumbnail)
const STATES = { auto: 0, cut: 1, forced: 2, expert: 3 };

const app = {
  state: null, seq: 0, tau: 0.95, graph: null, renderer: null, nodeIndex: new Map(),
  src: null, dst: null, prob: null, edgeState: null, label: null, size: null, kept: null, links: null,
  selected: null, matches: null, verified: new Set(), pairList: [], pairPos: 0, pair: null,
  timings: [],
};
window.coindie = app; // read by the end-to-end tests and the benchmark

const $ = (id) => document.getElementById(id);

async function api(path, options = {}) {
  const headers = { "X-Coindie-Token": TOKEN, ...(options.body ? { "Content-Type": "application/json" } : {}) };
  const response = await fetch(path, { ...options, headers });
  const type = response.headers.get("content-type") || "";
  const body = type.includes("json") ? await response.json() : await response.text();
  if (!response.ok) {
    const error = new Error(body.error || String(body));
    error.status = response.status;
    throw error;
  }
  return body;
}

function toast(message, isError = false) {
  const t = $("toast");
  t.textContent = message;
  t.className = "show" + (isError ? " error" : "");
  clearTimeout(toast.timer);
  toast.timer = setTimeout(() => (t.className = ""), isError ? 8000 : 3000);
}

// ------------------------------------------------------------------------------------------- face ids
// The same rule as coindie.ids: "L" + number + D/R, the number padded to 4 digits (L82D == L0082D).
function canonicalId(text) {
  const m = /^\s*L0*(\d+)([DR])\s*$/i.exec(text);
  return m ? "L" + m[1].padStart(4, "0") + m[2].toUpperCase() : text.trim();
}

// ------------------------------------------------------------------------------------------- clusters
function components() {
  const n = app.state.nodes.length;
  const parent = new Int32Array(n);
  for (let k = 0; k < n; k++) parent[k] = k;
  const find = (x) => {
    while (parent[x] !== x) { parent[x] = parent[parent[x]]; x = parent[x]; }
    return x;
  };
  const union = (x, y) => {
    const a = find(x), b = find(y);
    if (a !== b) parent[Math.max(a, b)] = Math.min(a, b);
  };
  const m = app.prob.length;
  const kept = new Uint8Array(m);
  const tree = app.links !== null;
  if (tree) { // the sides' trees: their merges above t (the server left out those an expert cut)
    const { src, dst, value } = app.links;
    for (let l = 0; l < value.length; l++) if (value[l] > app.tau) union(src[l], dst[l]);
  }
  for (let e = 0; e < m; e++) {
    const s = app.edgeState[e];
    if (s === 1) continue;
    if (s === 2 || (!tree && app.prob[e] > app.tau)) { kept[e] = 1; union(app.src[e], app.dst[e]); }
  }
  const label = new Int32Array(n), size = new Int32Array(n);
  for (let k = 0; k < n; k++) { label[k] = find(k); size[label[k]]++; }
  if (tree) { // drawn: the scored links inside each cluster
    for (let e = 0; e < m; e++) if (app.edgeState[e] !== 1 && label[app.src[e]] === label[app.dst[e]]) kept[e] = 1;
  }
  for (let k = 0; k < n; k++) size[k] = size[label[k]];
  app.label = label; app.size = size; app.kept = kept;
  let clusters = 0, singletons = 0;
  for (let k = 0; k < n; k++) if (label[k] === k) { clusters++; if (size[k] === 1) singletons++; }
  app.counts = { clusters, singletons };
  const groups = new Map();
  for (let k = 0; k < n; k++) {
    if (!groups.has(label[k])) groups.set(label[k], []);
    groups.get(label[k]).push(app.state.nodes[k].id);
  }
  app.verifiedNodes = new Uint8Array(n);
  for (const [root, members] of groups) {
    if (app.verified.has(members.slice().sort().join(","))) {
      for (const f of members) app.verifiedNodes[app.nodeIndex.get(f)] = 1;
    }
  }
  $("counts").textContent = `${clusters} clusters, ${singletons} singletons`;
}

function colour(k) {
  if (app.size[k] === 1) return SINGLETON;
  return PALETTE[(app.label[k] * 7919) % PALETTE.length];
}

function visible(k) {
  const node = app.state.nodes[k];
  const face = $("filter-face").value;
  if (face && node.side !== face) return false;
  if (app.size[k] < (parseInt($("filter-size").value, 10) || 1)) return false;
  if ($("filter-unverified").checked && app.verifiedNodes[k]) return false;
  return true;
}

function redraw() {
  const t0 = performance.now();
  components();
  app.renderer.refresh({ skipIndexation: true }); // positions never change: only colours and visibility
  const computed = performance.now() - t0;
  requestAnimationFrame(() => {
    // computed: clusters + sigma's reducers and buffers (main thread); frame: until the next frame is shown
    app.timings.push({ computed, frame: performance.now() - t0 });
  });
}

// -------------------------------------------------------------------------------------------- loading
async function loadState() {
  const state = await api("/api/state");
  app.state = state;
  app.seq = state.seq;
  app.verified = new Set(state.verified.map((v) => v.slice().sort().join(",")));
  $("title").textContent = "coindie · " + state.name;
  const m = state.edges.length;
  app.src = new Int32Array(m); app.dst = new Int32Array(m);
  app.prob = new Float32Array(m); app.edgeState = new Uint8Array(m);
  state.edges.forEach(([s, t, p, st], e) => {
    app.src[e] = s; app.dst[e] = t; app.prob[e] = p; app.edgeState[e] = STATES[st];
  });
  app.links = null;
  if (state.links) {
    const l = state.links.length;
    app.links = { src: new Int32Array(l), dst: new Int32Array(l), value: new Float64Array(l) };
    state.links.forEach(([s, t, v], k) => { app.links.src[k] = s; app.links.dst[k] = t; app.links.value[k] = v; });
  }
  $("threshold-label").title = state.links
    ? `Each side's clusters as coindie cluster --auto cuts them at ${state.threshold} (${state.how}); ` +
      "right: stricter, left: looser"
    : "Links with a probability above τ count";
  $("threshold-name").textContent = state.links ? "cut" : "τ";
  app.nodeIndex = new Map(state.nodes.map((n, k) => [n.id, k]));
  components(); // the reducers read the clusters as soon as the renderer exists
  buildGraph();
  redraw();
  if (app.selected) showFace(app.selected);
  $("undo").disabled = state.undo_target == null;
  $("redo").disabled = state.redo_target == null;
}

function buildGraph() {
  const graph = new Graph({ type: "undirected", multi: true });
  const n = app.state.nodes.length;
  const nodeSize = n > 500 ? 3 : 6;
  app.state.nodes.forEach((node) => graph.addNode(node.id, { x: node.x, y: node.y, size: nodeSize, label: node.id }));
  for (let e = 0; e < app.prob.length; e++) {
    graph.addEdgeWithKey(String(e), app.state.nodes[app.src[e]].id, app.state.nodes[app.dst[e]].id, { e });
  }
  if (app.renderer) {
    app.renderer.setGraph(graph);
  } else {
    app.renderer = new Sigma(graph, $("graph"), {
      labelRenderedSizeThreshold: 9, zIndex: true, preserveDrawingBuffer: true,
      nodeReducer: (node, data) => {
        const k = app.nodeIndex.get(node);
        const out = { ...data, color: colour(k) };
        if (!visible(k)) out.hidden = true;
        if (app.matches && !app.matches.has(node)) { out.color = "#e4e0da"; out.label = ""; }
        if (node === app.selected) { out.highlighted = true; out.size = data.size * 1.8; out.zIndex = 2; }
        if (app.verifiedNodes && app.verifiedNodes[k]) out.size = (out.size || data.size) * 1.3;
        return out;
      },
      edgeReducer: (edge, data) => {
        const e = data.e;
        const s = app.edgeState[e];
        if (!app.kept[e] || !visible(app.src[e]) || !visible(app.dst[e])) return { ...data, hidden: true };
        return { ...data, color: s === 2 ? "#2a8a2a" : s === 3 ? "#aa7700" : "#9c9588", size: s === 2 ? 2 : 1 };
      },
    });
    app.renderer.on("clickNode", ({ node }) => showFace(node));
    app.renderer.on("enterNode", ({ node, event }) => hover(node, event));
    app.renderer.on("leaveNode", () => ($("hover").style.display = "none"));
  }
  app.graph = graph;
}

function hover(node, event) {
  if (!app.state.has_images) return;
  const img = $("hover");
  img.src = `/api/faces/${encodeURIComponent(node)}/thumbnail.png`;
  const rect = $("graph").getBoundingClientRect();
  img.style.left = rect.left + event.x + 16 + "px";
  img.style.top = rect.top + event.y + 16 + "px";
  img.style.display = "block";
}

// ---------------------------------------------------------------------------------------- coin panel
async function showFace(face) {
  app.selected = face;
  app.renderer.refresh();
  let info;
  try {
    info = await api(`/api/faces/${encodeURIComponent(face)}?threshold=${app.tau}`);
  } catch (error) { toast(error.message, true); return; }
  const panel = $("panel");
  const thumb = (f) => (app.state.has_images ? `<img loading="lazy" src="/api/faces/${encodeURIComponent(f)}/thumbnail.png" alt="">` : "");
  const rows = info.neighbours.slice(0, NEIGHBOURS).map((n) =>
    `<tr class="neighbour" data-face="${n.face}"><td>${thumb(n.face)}</td><td class="state-${n.state}">${n.face}</td>` +
    `<td>${n.probability.toFixed(3)}</td><td>${n.state === "auto" ? "" : n.state}</td></tr>`).join("");
  panel.innerHTML = `<h2 id="face-id">${info.face}</h2>
    ${app.state.has_images ? `<img class="thumb" src="/api/faces/${encodeURIComponent(info.face)}/thumbnail.png" alt="relief">` : "<p class='hint'>no image (bare graph)</p>"}
    <p>Cluster of ${info.cluster.length}${info.verified ? " · <b>verified</b>" : ""}:</p>
    <p class="members">${info.cluster.map((f) => `<span data-face="${f}">${f}</span>`).join("")}</p>
    <p><button id="verify">Mark cluster verified</button> <button id="isolate">Make singleton</button>
      <button id="move">Move to cluster of…</button> <button id="split">Split off…</button></p>
    <h3>Neighbours (by probability)</h3>
    <table id="neighbours">${rows}</table>`;
  panel.querySelectorAll("tr.neighbour").forEach((tr, k) =>
    tr.addEventListener("click", () => openPair(info.face, info.neighbours.map((n) => n.face), k)));
  panel.querySelectorAll(".members span").forEach((s) => s.addEventListener("click", () => showFace(s.dataset.face)));
  $("verify").onclick = () => edit("verify", info.face, null, { members: info.cluster });
  $("isolate").onclick = () => edit("move", info.face, null);
  $("move").onclick = () => {
    const other = prompt("Move " + info.face + " to the cluster of which face?");
    if (other) edit("move", info.face, canonicalId(other));
  };
  $("split").onclick = () => {
    const text = prompt("Faces that leave this cluster (with " + info.face + "), separated by spaces:", info.face);
    if (!text) return;
    const group = text.split(/[\s,]+/).filter(Boolean).map(canonicalId);
    const rest = info.cluster.filter((f) => !group.includes(f));
    edit("split", info.face, null, { group, rest });
  };
  $("link-a").value = info.face;
}

// ---------------------------------------------------------------------------------------------- edits
async function edit(action, a, b, payload = {}) {
  try {
    const result = await api("/api/edits", {
      method: "POST",
      body: JSON.stringify({ action, a, b, payload, base_seq: app.seq, client: CLIENT, threshold: app.tau }),
    });
    toast(`saved: edit ${result.edit.edit_id} (${action}${a ? " " + a : ""}${b ? " " + b : ""})`);
    await loadState();
    return result;
  } catch (error) {
    toast(error.message, true);
    if (error.status === 409) await loadState();
    return null;
  }
}

async function poll() {
  if (app.pollPaused) { setTimeout(poll, 1500); return; } // the tests' stale tab
  try {
    const news = await api(`/api/edits?since=${app.seq}`);
    if (news.seq > app.seq) {
      const others = news.edits.filter((e) => e.payload.client !== CLIENT).length;
      await loadState();
      if (others) toast(`${others} new edit(s) from another tab or user`);
    }
  } catch (error) { /* the server may be restarting */ }
  setTimeout(poll, 1500);
}

// ---------------------------------------------------------------------------------------------- search
function search(text) {
  const q = text.trim();
  if (!q) { app.matches = null; app.renderer.refresh(); return; }
  const key = canonicalId(q);
  const exact = app.nodeIndex.has(key) ? [key] : [];
  const lower = q.toLowerCase();
  const found = exact.length ? exact : app.state.nodes.map((n) => n.id).filter((id) => id.toLowerCase().includes(lower));
  app.matches = new Set(found);
  app.renderer.refresh();
  if (found.length) {
    const data = app.renderer.getNodeDisplayData(found[0]);
    if (data) app.renderer.getCamera().animate({ x: data.x, y: data.y, ratio: 0.25 }, { duration: 300 });
    if (found.length === 1) showFace(found[0]);
  } else toast(`no face matches ${q}`, true);
}

// ------------------------------------------------------------------------------------------ pair view
async function openPair(a, candidates, position) {
  app.pairList = candidates; app.pairPos = position;
  await showPair(a, candidates[position]);
}

async function showPair(a, b) {
  let info;
  try { info = await api(`/api/pairs/${encodeURIComponent(a)}/${encodeURIComponent(b)}`); }
  catch (error) { toast(error.message, true); return; }
  app.pair = { a, b, info };
  $("pair").hidden = false;
  $("fix").hidden = true;
  $("pair-title").textContent = `${info.target} ← ${info.source}`;
  $("pair-info").textContent = `p = ${info.probability.toFixed(3)} · ${info.origin} · ${info.method}` +
    (info.valid ? "" : ` · invalid: ${info.reason}`);
  const base = `/api/pairs/${encodeURIComponent(a)}/${encodeURIComponent(b)}`;
  const stamp = "?seq=" + app.seq;
  if (info.has_images) {
    for (const kind of ["target", "source", "difference", "heat"]) $("img-" + kind).src = `${base}/${kind}.png${stamp}`;
    $("ov-target").src = `${base}/target.png${stamp}`;
    $("ov-source").src = `${base}/source.png${stamp}`;
    $("ov-source").style.opacity = $("blend").value;
    api(`${base}/clouds.json`).then((c) => threeView($("three"), c)).catch((e) => toast(e.message, true));
  }
  drawHistogram(info.histogram, info.max_distance_mm);
}

function drawHistogram(values, maxDistance) {
  const canvas = $("histogram");
  const g = canvas.getContext("2d");
  g.clearRect(0, 0, canvas.width, canvas.height);
  if (!values) { g.fillText("no histogram (bare graph)", 10, 20); return; }
  const top = Math.max(...values, 1e-9);
  const w = (canvas.width - 30) / values.length, h = canvas.height - 30;
  g.fillStyle = "#8b5e34";
  values.forEach((v, k) => g.fillRect(25 + k * w, 10 + h - (v / top) * h, Math.max(w - 1, 1), (v / top) * h));
  g.fillStyle = "#333";
  g.fillText("0", 22, canvas.height - 6);
  g.fillText(maxDistance.toFixed(2) + " mm", canvas.width - 50, canvas.height - 6);
}

function stepPair(delta) {
  if (!app.pair || !app.pairList.length) return;
  app.pairPos = (app.pairPos + delta + app.pairList.length) % app.pairList.length;
  showPair(app.pair.a, app.pairList[app.pairPos]);
}

async function decide(accept) {
  if (!app.pair) return;
  await edit(accept ? "link" : "cut", app.pair.a, app.pair.b);
  stepPair(1);
}

let flickerTimer = null;
function flicker() {
  if (flickerTimer) { clearInterval(flickerTimer); flickerTimer = null; $("ov-source").style.opacity = $("blend").value; return; }
  let on = false;
  flickerTimer = setInterval(() => { on = !on; $("ov-source").style.opacity = on ? 1 : 0; }, 400);
}

// ------------------------------------------------------------------------------ manual registration
const picks = { target: [], source: [] };
function openFix() {
  if (!app.pair || !app.pair.info.has_images) { toast("no scans: nothing to register", true); return; }
  const { target, source } = app.pair.info;
  $("fix").hidden = false;
  picks.target = []; picks.source = [];
  for (const [role, face] of [["target", target], ["source", source]]) {
    const box = $("pick-" + role);
    box.querySelectorAll(".mark").forEach((m) => m.remove());
    box.querySelector("img").src = `/api/faces/${encodeURIComponent(face)}/relief.png`;
  }
  updateFix();
}

function pickAt(role, event) {
  const img = $("pick-" + role).querySelector("img");
  const rect = img.getBoundingClientRect();
  const col = ((event.clientX - rect.left) * img.naturalWidth) / rect.width;
  const row = ((event.clientY - rect.top) * img.naturalHeight) / rect.height;
  picks[role].push([col, row]);
  const mark = document.createElement("div");
  mark.className = "mark";
  mark.textContent = picks[role].length;
  mark.style.left = event.clientX - rect.left + "px";
  mark.style.top = event.clientY - rect.top + "px";
  $("pick-" + role).appendChild(mark);
  updateFix();
}

function updateFix() {
  const n = Math.min(picks.target.length, picks.source.length);
  $("fix-count").textContent = `${picks.target.length} on the target, ${picks.source.length} on the source`;
  $("fix-run").disabled = !(n >= 3 && picks.target.length === picks.source.length);
}

async function runFix() {
  const { target, source } = app.pair.info;
  $("fix-run").disabled = true;
  try {
    const result = await api(`/api/pairs/${encodeURIComponent(target)}/${encodeURIComponent(source)}/register`, {
      method: "POST",
      body: JSON.stringify({ target_pixels: picks.target, source_pixels: picks.source, reason: $("fix-reason").value,
        base_seq: app.seq, client: CLIENT }),
    });
    toast(`re-aligned: p = ${result.probability.toFixed(3)} (${result.note})`);
    await loadState();
    await showPair(app.pair.a, app.pair.b);
  } catch (error) { toast(error.message, true); updateFix(); }
}

// -------------------------------------------------------------------------------------------- queue
async function showQueue() {
  const { items } = await api(`/api/queue?threshold=${app.tau}`);
  $("queue").hidden = false;
  $("queue-list").innerHTML = items.map((it, k) =>
    `<li data-k="${k}">${it.a} – ${it.b}: ${it.kind} (${it.why})</li>`).join("") || "<li>nothing uncertain</li>";
  $("queue-list").querySelectorAll("li[data-k]").forEach((li) => li.addEventListener("click", () => {
    const it = items[+li.dataset.k];
    $("queue").hidden = true;
    openPair(it.a, [it.b], 0);
  }));
}

// ------------------------------------------------------------------------------------------ exports
function viewPng() {
  app.renderer.refresh(); // WebGL keeps its drawing only until the frame is shown: copy it right after a render
  const canvases = app.renderer.getCanvases();
  const first = Object.values(canvases)[0];
  const out = document.createElement("canvas");
  out.width = first.width; out.height = first.height;
  const g = out.getContext("2d");
  g.fillStyle = "#fff"; g.fillRect(0, 0, out.width, out.height);
  for (const name of ["edges", "nodes", "labels", "hovers", "hoverNodes"]) if (canvases[name]) g.drawImage(canvases[name], 0, 0);
  return out.toDataURL("image/png");
}

function viewSvg() {
  const { width, height } = app.renderer.getDimensions();
  const parts = [`<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}">`,
    `<rect width="100%" height="100%" fill="#fff"/>`];
  const pos = (k) => app.renderer.graphToViewport(app.renderer.getNodeDisplayData(app.state.nodes[k].id));
  for (let e = 0; e < app.prob.length; e++) {
    if (!app.kept[e] || !visible(app.src[e]) || !visible(app.dst[e])) continue;
    const a = pos(app.src[e]), b = pos(app.dst[e]);
    parts.push(`<line x1="${a.x.toFixed(1)}" y1="${a.y.toFixed(1)}" x2="${b.x.toFixed(1)}" y2="${b.y.toFixed(1)}" stroke="#9c9588"/>`);
  }
  app.state.nodes.forEach((node, k) => {
    if (!visible(k)) return;
    const p = pos(k);
    parts.push(`<circle cx="${p.x.toFixed(1)}" cy="${p.y.toFixed(1)}" r="4" fill="${colour(k)}"><title>${node.id}</title></circle>`);
  });
  parts.push("</svg>");
  return "data:image/svg+xml;charset=utf-8," + encodeURIComponent(parts.join("\n"));
}

// ------------------------------------------------------------------------------------------ wiring
function wire() {
  const slider = $("threshold");
  slider.value = app.tau;
  $("threshold-value").textContent = app.tau.toFixed(2);
  slider.addEventListener("input", () => {
    app.tau = parseFloat(slider.value);
    $("threshold-value").textContent = app.tau.toFixed(2);
    redraw();
  });
  $("search").addEventListener("change", (e) => search(e.target.value));
  $("search").addEventListener("keydown", (e) => { if (e.key === "Enter") search(e.target.value); });
  for (const id of ["filter-face", "filter-size", "filter-unverified"]) $(id).addEventListener("input", redraw);
  $("undo").onclick = () => app.state.undo_target != null && edit("undo", null, null, { target: app.state.undo_target });
  $("redo").onclick = () => app.state.redo_target != null && edit("redo", null, null, { target: app.state.redo_target });
  $("link-create").onclick = () => edit("link", canonicalId($("link-a").value), canonicalId($("link-b").value));
  $("link-cut").onclick = () => edit("cut", canonicalId($("link-a").value), canonicalId($("link-b").value));
  $("queue-button").onclick = showQueue;
  $("queue-close").onclick = () => ($("queue").hidden = true);
  $("pair-close").onclick = () => { $("pair").hidden = true; app.pair = null; };
  $("pair-accept").onclick = () => decide(true);
  $("pair-reject").onclick = () => decide(false);
  $("pair-fix").onclick = openFix;
  $("fix-run").onclick = runFix;
  $("fix-clear").onclick = openFix;
  $("pick-target").addEventListener("click", (e) => pickAt("target", e));
  $("pick-source").addEventListener("click", (e) => pickAt("source", e));
  $("blend").addEventListener("input", (e) => ($("ov-source").style.opacity = e.target.value));
  $("flicker").onclick = flicker;
  document.querySelectorAll("[data-export]").forEach((a) => {
    a.addEventListener("click", () => (a.href = `/api/export/${a.dataset.export}?threshold=${app.tau}`));
    a.href = `/api/export/${a.dataset.export}?threshold=${app.tau}`;
  });
  $("export-png").addEventListener("click", (e) => (e.currentTarget.href = viewPng()));
  $("export-svg").addEventListener("click", (e) => (e.currentTarget.href = viewSvg()));
  document.addEventListener("keydown", (e) => {
    if (e.target.tagName === "INPUT" && e.target.type !== "range") return;
    if ((e.ctrlKey || e.metaKey) && e.key === "z") { $("undo").click(); e.preventDefault(); return; }
    if ((e.ctrlKey || e.metaKey) && e.key === "y") { $("redo").click(); e.preventDefault(); return; }
    if ($("pair").hidden) return;
    if (e.key === "ArrowRight" || e.key === "j") stepPair(1);
    else if (e.key === "ArrowLeft" || e.key === "k") stepPair(-1);
    else if (e.key === "a") decide(true);
    else if (e.key === "r") decide(false);
    else if (e.key === "Escape") $("pair-close").click();
  });
}

async function main() {
  try {
    const state = await api("/api/state");
    app.tau = state.threshold;
    wire();
    await loadState();
    app.ready = true;
    poll();
  } catch (error) {
    console.error(error.stack);
    document.body.innerHTML = `<p style="padding:2em">coindie: ${error.message}</p>`;
  }
}

main();
