// pathtracer view: shows the linear film the server sends (half floats,
// see src/preview/frame.rs) with the exposure, tone curve and gamma chosen
// here, so that changing them never asks for a new render. The server
// announces each new frame by a server-sent event.
"use strict";

const $ = (id) => document.getElementById(id);
const canvas = $("image");
const context = canvas.getContext("2d");

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
let fetching = false;
let wanted = 0;
let draws = 0;
let controlsSet = false;

// The tone curves of src/image_io/tonemap.rs.
function tone(c, curve) {
  if (curve === "none") return c;
  if (c === Infinity) return 1;
  if (curve === "reinhard") return c / (1 + c);
  return Math.min(1, (c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14));
}

// The 8-bit mapping of src/image_io/quantize.rs: 2^exposure, the curve,
// clamp to [0, 1], 1/gamma, times 255 truncated.
function draw() {
  if (!shown.film) return;
  const { film, width, height } = shown;
  if (canvas.width !== width || canvas.height !== height) {
    canvas.width = width;
    canvas.height = height;
  }
  const scale = 2 ** Number($("exposure").value);
  const curve = $("tonemap").value;
  const gamma = Number($("gamma").value);
  const inverse = gamma > 0 ? 1 / gamma : 0;
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
  draws += 1;
  document.body.dataset.draws = String(draws);
  document.body.dataset.frame = String(shown.frame);
}

function decode(buffer) {
  const view = new DataView(buffer);
  const magic = String.fromCharCode(...new Uint8Array(buffer, 0, 4));
  if (magic !== "PTVF") throw new Error("not a film frame");
  const width = view.getUint32(4, true);
  const height = view.getUint32(8, true);
  const frame = view.getUint32(12, true);
  const count = width * height * 3;
  const film = new Float32Array(count);
  for (let i = 0; i < count; i++) film[i] = HALF[view.getUint16(16 + 2 * i, true)];
  return { film, width, height, frame };
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
      const decoded = decode(await response.arrayBuffer());
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
  $("progress").textContent =
    `${status.width}x${status.height}, ${status.spp.toFixed(0)} of ${status.spp_target} spp` +
    `${status.done ? " (done)" : ""}, ${rate} M samples/s, ${status.seconds.toFixed(1)} s` +
    (status.render > 1 ? `, render ${status.render}` : "");
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
  if (status.frame > shown.frame) fetchFrame(status.frame);
}

function showPixel(event) {
  if (!shown.film) return;
  const box = canvas.getBoundingClientRect();
  const x = Math.floor(((event.clientX - box.left) / box.width) * shown.width);
  const y = Math.floor(((event.clientY - box.top) / box.height) * shown.height);
  if (x < 0 || y < 0 || x >= shown.width || y >= shown.height) return;
  const i = (y * shown.width + x) * 3;
  const value = (c) => shown.film[i + c].toPrecision(4);
  $("pixel").textContent = `(${x}, ${y}): ${value(0)} ${value(1)} ${value(2)} (linear RGB)`;
}

$("exposure").addEventListener("input", () => {
  $("exposure-value").value = Number($("exposure").value).toFixed(1);
  draw();
});
$("tonemap").addEventListener("change", draw);
$("gamma").addEventListener("change", draw);
$("zoom").addEventListener("click", () => {
  const stage = $("stage");
  const fit = stage.classList.toggle("fit");
  stage.classList.toggle("actual", !fit);
  $("zoom").textContent = fit ? "1:1" : "fit";
});
canvas.addEventListener("mousemove", showPixel);
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
  $("progress").textContent += " (disconnected: is pathtracer view still running?)";
};
