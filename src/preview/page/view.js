// pathtracer view: shows the linear film the server sends (half floats,
// see src/preview/frame.rs) with the exposure, tone curve and gamma chosen
// here, so that changing them never asks for a new render. The server
// announces each new frame, and each measure against --against's image,
// by a server-sent event.
"use strict";

const $ = (id) => document.getElementById(id);
const ours = $("image");
const theirs = $("theirs");
const heat = $("heat");
const layers = $("layers");
const stage = $("stage");

// Every half float's value, by its 16 bits.
const HALF = (() => {
  const table = new Float32Array(65536);
  for (let bits = 0; bits < 65536; bits++) {
    const sign = bits & 0x8000 ? -1 : 1;
    const exponent = (bits >> 10) & 0x1f;
    const mantissa = bits & 0x3ff;
    let value;
    if (exponent === 0) value = mantissa * 2 ** -24;
    else if (exponent === 31) value = mantissa ? NaN : Infinity;
    else value = (1 + mantissa / 1024) * 2 ** (exponent - 15);
    table[bits] = sign * value;
  }
  return table;
})();

const shown = { film: null, width: 0, height: 0, frame: 0 };
const compared = { bytes: null, frame: 0, width: 0, height: 0 };
const view = { zoom: 1, x: 0, y: 0, fitted: true };
let wanted = 0;
let fetching = false;
let draws = 0;
let controlsSet = false;
let progressText = "";

// The tone curves of src/image_io/tonemap.rs.
function tone(c, curve) {
  if (curve === "none") return c;
  if (c === Infinity) return 1;
  if (curve === "reinhard") return c / (1 + c);
  return Math.min(1, (c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14));
}

function sized(canvas, width, height) {
  if (canvas.width !== width || canvas.height !== height) {
    canvas.width = width;
    canvas.height = height;
    canvas.style.width = `${width}px`;
    canvas.style.height = `${height}px`;
    return true;
  }
  return false;
}

// The 8-bit mapping of src/image_io/quantize.rs: 2^exposure, the curve,
// clamp to [0, 1], 1/gamma, times 255 truncated.
function draw() {
  if (!shown.film) return;
  const { film, width, height } = shown;
  const resized = sized(ours, width, height);
  const scale = 2 ** Number($("exposure").value);
  const curve = $("tonemap").value;
  const gamma = Number($("gamma").value);
  const inverse = gamma > 0 ? 1 / gamma : 0;
  const context = ours.getContext("2d");
  const image = context.createImageData(width, height);
  const out = image.data;
  for (let pixel = 0, i = 0; pixel < width * height; pixel++) {
    for (let channel = 0; channel < 3; channel++, i++) {
      let c = film[i] * scale;
      c = c > 0 ? tone(c, curve) : 0;
      c = Math.min(1, c);
      if (inverse) c = c ** inverse;
      out[pixel * 4 + channel] = Math.trunc(c * 255);
    }
    out[pixel * 4 + 3] = 255;
  }
  context.putImageData(image, 0, 0);
  if (resized || view.fitted) fit();
  draws += 1;
  document.body.dataset.draws = String(draws);
  document.body.dataset.frame = String(shown.frame);
}

function header(buffer, magic) {
  const view = new DataView(buffer);
  const found = String.fromCharCode(...new Uint8Array(buffer, 0, 4));
  if (found !== magic) throw new Error(`not a ${magic} frame`);
  return { view, width: view.getUint32(4, true), height: view.getUint32(8, true), frame: view.getUint32(12, true) };
}

function decodeFilm(buffer) {
  const { view, width, height, frame } = header(buffer, "PTVF");
  const count = width * height * 3;
  const film = new Float32Array(count);
  for (let i = 0; i < count; i++) film[i] = HALF[view.getUint16(16 + 2 * i, true)];
  return { film, width, height, frame };
}

// A display frame (src/preview/compare.rs) drawn as it is.
function drawDisplay(buffer, canvas) {
  const { width, height, frame } = header(buffer, "PTVD");
  sized(canvas, width, height);
  const bytes = new Uint8Array(buffer, 16);
  const context = canvas.getContext("2d");
  const image = context.createImageData(width, height);
  for (let pixel = 0; pixel < width * height; pixel++) {
    image.data.set(bytes.subarray(pixel * 3, pixel * 3 + 3), pixel * 4);
    image.data[pixel * 4 + 3] = 255;
  }
  context.putImageData(image, 0, 0);
  return { bytes, width, height, frame };
}

async function fetchFrame(frame) {
  wanted = Math.max(wanted, frame);
  if (fetching) return;
  fetching = true;
  try {
    while (wanted > shown.frame) {
      const target = wanted;
      const response = await fetch("/film", { cache: "no-store" });
      if (!response.ok) break;
      const decoded = decodeFilm(await response.arrayBuffer());
      Object.assign(shown, decoded);
      // The latest film may be newer than the one announced.
      shown.frame = Math.max(decoded.frame, target);
      draw();
    }
  } catch (error) {
    $("progress").textContent = `cannot read the film: ${error}`;
  } finally {
    fetching = false;
  }
}

async function fetchComparison(frame) {
  if (frame <= compared.frame) return;
  compared.frame = frame;
  const [theirsAnswer, heatAnswer] = await Promise.all([
    fetch("/against", { cache: "no-store" }),
    fetch("/heat", { cache: "no-store" }),
  ]);
  if (!theirsAnswer.ok || !heatAnswer.ok) return;
  Object.assign(compared, drawDisplay(await theirsAnswer.arrayBuffer(), theirs));
  drawDisplay(await heatAnswer.arrayBuffer(), heat);
  document.body.dataset.compared = String(frame);
  showMode();
}

function showFigures(against) {
  $("comparing").hidden = !against;
  if (!against) return;
  const figures = $("figures");
  if (against.error) {
    figures.textContent = `${against.image}: ${against.error}`;
    figures.className = "differs";
    return;
  }
  figures.className = against.same ? "same" : "differs";
  figures.textContent =
    `${against.image}: ${against.same ? "looks the same" : "looks different"}` +
    ` (mean ${against.mean.toFixed(2)}, p95 ${against.p95.toFixed(1)} of 255; same at most 4 and 12)` +
    `, FLIP ${against.flip.toFixed(4)}` +
    (against.aspect_differs ? ", aspect ratios differ" : "") +
    `; measured at ${against.spp.toFixed(0)} spp in ${against.seconds.toFixed(2)} s`;
  fetchComparison(against.frame);
  showMode();
}

function showStatus(status) {
  if (!controlsSet) {
    controlsSet = true;
    $("exposure").value = status.exposure;
    $("exposure-value").value = Number(status.exposure).toFixed(1);
    $("tonemap").value = status.tonemap;
    $("gamma").value = status.gamma === null ? "" : String(status.gamma);
  }
  $("scene").textContent = status.scene;
  document.title = `${status.scene}: pathtracer view`;
  const rate = (status.samples_per_second / 1e6).toFixed(2);
  progressText =
    `${status.width}x${status.height}, ${status.spp.toFixed(0)} of ${status.spp_target} spp` +
    `${status.done ? " (done)" : ""}, ${rate} M samples/s, ${status.seconds.toFixed(1)} s` +
    (status.render > 1 ? `, render ${status.render}` : "");
  $("progress").textContent = progressText;
  $("progress").classList.remove("stale");
  $("error").hidden = !status.error;
  $("error").textContent = status.error || "";
  const warnings = $("warnings");
  warnings.replaceChildren(...status.warnings.map((text) => {
    const item = document.createElement("li");
    item.textContent = text;
    return item;
  }));
  warnings.hidden = status.warnings.length === 0;
  showFigures(status.against);
  if (status.frame > shown.frame) fetchFrame(status.frame);
}

// Which layers show: ours under theirs (clipped at the split) or the map.
function showMode() {
  const mode = $("mode").value;
  const comparing = !$("comparing").hidden && compared.bytes !== null;
  theirs.hidden = !comparing || (mode !== "split" && mode !== "theirs");
  heat.hidden = !comparing || mode !== "heat";
  $("split").hidden = mode !== "split";
  theirs.style.clipPath = mode === "split" ? `inset(0 0 0 ${$("split").value}%)` : "none";
}

function place() {
  layers.style.transform = `translate(${view.x}px, ${view.y}px) scale(${view.zoom})`;
}

function fit() {
  const width = shown.width || 1;
  const height = shown.height || 1;
  view.zoom = Math.min(stage.clientWidth / width, stage.clientHeight / height);
  view.x = (stage.clientWidth - width * view.zoom) / 2;
  view.y = (stage.clientHeight - height * view.zoom) / 2;
  view.fitted = true;
  place();
}

function actualSize() {
  view.zoom = 1;
  view.x = Math.round((stage.clientWidth - shown.width) / 2);
  view.y = Math.round((stage.clientHeight - shown.height) / 2);
  view.fitted = false;
  place();
}

stage.addEventListener("wheel", (event) => {
  event.preventDefault();
  const box = stage.getBoundingClientRect();
  const cx = event.clientX - box.left;
  const cy = event.clientY - box.top;
  const factor = Math.exp(-event.deltaY * 0.002);
  const zoom = Math.min(64, Math.max(1 / 64, view.zoom * factor));
  view.x = cx - ((cx - view.x) * zoom) / view.zoom;
  view.y = cy - ((cy - view.y) * zoom) / view.zoom;
  view.zoom = zoom;
  view.fitted = false;
  place();
}, { passive: false });

let drag = null;
stage.addEventListener("pointerdown", (event) => {
  drag = { x: event.clientX - view.x, y: event.clientY - view.y };
  stage.classList.add("dragging");
  stage.setPointerCapture(event.pointerId);
});
stage.addEventListener("pointerup", () => {
  drag = null;
  stage.classList.remove("dragging");
});
stage.addEventListener("pointermove", (event) => {
  if (drag) {
    view.x = event.clientX - drag.x;
    view.y = event.clientY - drag.y;
    view.fitted = false;
    place();
  }
  showPixel(event);
});

function showPixel(event) {
  if (!shown.film) return;
  const box = ours.getBoundingClientRect();
  const x = Math.floor(((event.clientX - box.left) / box.width) * shown.width);
  const y = Math.floor(((event.clientY - box.top) / box.height) * shown.height);
  if (x < 0 || y < 0 || x >= shown.width || y >= shown.height) {
    $("pixel").textContent = "\u00a0";
    return;
  }
  const i = (y * shown.width + x) * 3;
  const value = (c) => shown.film[i + c].toPrecision(4);
  let text = `(${x}, ${y}): ours ${value(0)} ${value(1)} ${value(2)} (linear RGB)`;
  if (compared.bytes && compared.width === shown.width && compared.height === shown.height) {
    const j = (y * shown.width + x) * 3;
    text += `, theirs ${compared.bytes[j]} ${compared.bytes[j + 1]} ${compared.bytes[j + 2]} (of 255)`;
  }
  text += `, zoom ${(view.zoom * 100).toFixed(0)}%`;
  $("pixel").textContent = text;
}

$("exposure").addEventListener("input", () => {
  $("exposure-value").value = Number($("exposure").value).toFixed(1);
  draw();
});
$("tonemap").addEventListener("change", draw);
$("gamma").addEventListener("change", draw);
$("fit").addEventListener("click", fit);
$("actual").addEventListener("click", actualSize);
$("mode").addEventListener("change", showMode);
$("split").addEventListener("input", showMode);
function flip() {
  $("mode").value = $("mode").value === "theirs" ? "ours" : "theirs";
  showMode();
}
$("flip").addEventListener("click", flip);
document.addEventListener("keydown", (event) => {
  if (event.key === "f" || event.key === "F") flip();
});
window.addEventListener("resize", () => { if (view.fitted) fit(); });
$("save").addEventListener("click", async () => {
  const query = new URLSearchParams({
    exposure: $("exposure").value,
    tonemap: $("tonemap").value,
    gamma: $("gamma").value,
  });
  $("saved").textContent = "saving…";
  try {
    const response = await fetch(`/save?${query}`, { method: "POST" });
    const text = await response.text();
    $("saved").textContent = response.ok ? `saved ${JSON.parse(text).saved}` : text;
  } catch (error) {
    $("saved").textContent = `not saved: ${error}`;
  }
});

const events = new EventSource("/events");
events.onmessage = (event) => showStatus(JSON.parse(event.data));
events.onerror = () => {
  $("progress").classList.add("stale");
  $("progress").textContent = `${progressText} (disconnected: is pathtracer view still running?)`;
};
