// Packs a live scene's module into the one file the book's page loads as a <script> (file://
// pages cannot fetch a .wasm): emscripten's JavaScript (linked without SINGLE_FILE), then its
// WebAssembly gzip-compressed and in base64, handed to the module by its instantiateWasm hook.
// SINGLE_FILE put the WebAssembly in uncompressed base64 (a third larger than the binary); this
// is less than half its size. The page unpacks it with the browser's DecompressionStream (no
// fetch, no network), node with zlib.
//   node pack.js <emscripten .js> <.wasm> <out .js> <factory name>
"use strict";
const fs = require("fs");
const zlib = require("zlib");

const [glue, wasm, out, name] = process.argv.slice(2);
if (!/^[A-Za-z_][A-Za-z0-9_]*$/.test(name || "")) {
  console.error("pack.js: usage: node pack.js <emscripten .js> <.wasm> <out .js> <factory name>");
  process.exit(2);
}
const packed = zlib.gzipSync(fs.readFileSync(wasm), { level: 9 }).toString("base64");
const hook = `
;(function () {
  var make = ${name}, packed = "${packed}";
  function bytes() {
    var text = atob(packed), b = new Uint8Array(text.length);
    for (var i = 0; i < text.length; i++) b[i] = text.charCodeAt(i);
    return b;
  }
  function unpack() {
    if (typeof DecompressionStream === "function")
      return new Response(new Blob([bytes()]).stream().pipeThrough(new DecompressionStream("gzip"))).arrayBuffer();
    return Promise.resolve(require("zlib").gunzipSync(Buffer.from(packed, "base64")));
  }
  ${name} = function (module) {
    module = module || {};
    return new Promise(function (resolve, reject) {
      module.instantiateWasm = function (imports, receive) {
        unpack().then(function (binary) { return WebAssembly.instantiate(binary, imports); })
          .then(function (r) { receive(r.instance, r.module); }, reject);
        return {};
      };
      make(module).then(resolve, reject);
    });
  };
  if (typeof module === "object" && module.exports === make) module.exports = ${name};
})();
`;
fs.writeFileSync(out, fs.readFileSync(glue, "utf8") + hook);
