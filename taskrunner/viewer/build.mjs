// Builds the web view into static/: the bundle (esbuild), the page and its style sheet,
// and THIRD_PARTY_LICENSES.txt, the licence text of every npm package whose code lands in
// the bundle (taken from the bundler's own list of inputs, so a new import cannot ship
// without its notice), and Swagger UI's prebuilt files for the API's /docs page.
// `npm ci && npm run build`; CI rebuilds and compares byte for byte.
import { copyFileSync, existsSync, readFileSync, readdirSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import * as esbuild from "esbuild";

const here = dirname(fileURLToPath(import.meta.url));
const out = join(here, "static");

const result = await esbuild.build({
  absWorkingDir: here,
  entryPoints: ["src/main.js"],
  bundle: true,
  minify: true,
  format: "iife",
  target: "es2020",
  legalComments: "linked",
  outfile: "static/viewer.js",
  metafile: true,
  logLevel: "info",
});
for (const name of ["index.html", "viewer.css"]) {
  copyFileSync(join(here, "src", name), join(out, name));
}

// The API's OpenAPI page (/docs) loads Swagger UI from here, not from a CDN, so that it
// works offline: swagger-ui-dist's prebuilt bundle, style sheet and icon, copied as shipped
// (the bundle's own notice of what it contains, swagger-ui-bundle.js.LICENSE.txt, beside it).
const swaggerFolder = "node_modules/swagger-ui-dist";
const swaggerFiles = [
  "swagger-ui-bundle.js",
  "swagger-ui-bundle.js.LICENSE.txt",
  "swagger-ui.css",
  "favicon-32x32.png",
];
for (const name of swaggerFiles) {
  const target = name.startsWith("favicon") ? `swagger-ui-${name}` : name;
  copyFileSync(join(here, swaggerFolder, name), join(out, target));
}

// node_modules/<name>/... or node_modules/@scope/<name>/... -> package folder, files in it
const packages = new Map();
for (const input of Object.keys(result.metafile.inputs)) {
  const parts = input.split("/");
  const at = parts.lastIndexOf("node_modules");
  if (at < 0) continue;
  const width = parts[at + 1].startsWith("@") ? 2 : 1;
  const folder = parts.slice(0, at + 1 + width).join("/");
  if (!packages.has(folder)) packages.set(folder, []);
  packages.get(folder).push(parts.slice(at + 1 + width).join("/"));
}
packages.set(swaggerFolder, [...swaggerFiles]);

const sections = [];
for (const folder of [...packages.keys()].sort()) {
  const meta = JSON.parse(readFileSync(join(here, folder, "package.json"), "utf8"));
  const own = readdirSync(join(here, folder))
    .filter((f) => /^(licen[cs]e|copying)/i.test(f))
    .sort();
  const keptName = `licenses/${meta.name.replace("/", "__")}.LICENSE`;
  const kept = join(here, keptName);
  let text;
  let origin;
  if (own.length > 0) {
    text = own.map((f) => readFileSync(join(here, folder, f), "utf8").trimEnd()).join("\n\n");
    origin = `${own.join(", ")} of the npm package`;
  } else if (existsSync(kept)) {
    text = readFileSync(kept, "utf8").trimEnd();
    origin = `the project's own copy, ${keptName} (the npm package ships none)`;
  } else {
    console.error(
      `build.mjs: ${meta.name} ${meta.version} (${meta.license}) is bundled into viewer.js ` +
        `but ships no licence file: add its licence text as ${keptName}`,
    );
    process.exit(1);
  }
  const notice = kept.replace(/\.LICENSE$/, ".NOTICE");
  const head = [
    `${meta.name} ${meta.version}, licence ${meta.license}`,
    meta.homepage ? `home: ${meta.homepage}` : null,
    `bundled files: ${packages.get(folder).sort().join(", ")}`,
    `licence text: ${origin}`,
  ].filter(Boolean);
  let section = `${head.join("\n")}\n\n${text}\n`;
  const ownNotice = join(here, folder, "NOTICE");
  if (existsSync(ownNotice)) {
    section += `\nNotice (NOTICE of the npm package):\n\n${readFileSync(ownNotice, "utf8").trimEnd()}\n`;
  } else if (existsSync(notice)) {
    section += `\nNotice:\n\n${readFileSync(notice, "utf8").trimEnd()}\n`;
  }
  if (folder === swaggerFolder) {
    const inner = readFileSync(join(here, folder, "swagger-ui-bundle.js.LICENSE.txt"), "utf8");
    section += `\nLicences of the code swagger-ui-bundle.js contains (its own ` +
      `swagger-ui-bundle.js.LICENSE.txt):\n\n${inner.trimEnd()}\n`;
  }
  sections.push(section);
}

const rule = "=".repeat(78);
writeFileSync(
  join(out, "THIRD_PARTY_LICENSES.txt"),
  "Third-party software bundled into viewer.js, and Swagger UI (swagger-ui-*)\n" +
    "(written by taskrunner/viewer/build.mjs from the bundler's inputs; do not edit)\n\n" +
    sections.map((s) => `${rule}\n${s}`).join("\n"),
);
console.log(`  static/THIRD_PARTY_LICENSES.txt  ${sections.length} packages`);
