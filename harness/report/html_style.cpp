// The HTML report's inline style sheet and script. The script only swaps an image for its
// reference while the pointer is over it (or on tap) and marks the page as ready
// (body[data-js=ready]), which the headless-browser test looks for.
#include "report/html_parts.h"

namespace raygate::report::html {

namespace {

// The palette and the page: colours as variables, so the verdict colours below stay one set.
std::string_view theme_style() {
  return R"css(
:root{--fg:#1f2328;--muted:#656d76;--line:#d8dee4;--soft:#eef1f4;--bg:#f3f5f7;--card:#fff;
--accent:#0969da;--pass:#1a7f37;--pass-bg:#dafbe1;--warn:#9a6700;--warn-bg:#fff8c5;
--fail:#cf222e;--fail-bg:#ffebe9;--unm:#8250df;--unm-bg:#fbefff;
--mono:ui-monospace,SFMono-Regular,Menlo,Consolas,"DejaVu Sans Mono","Liberation Mono",monospace}
*{box-sizing:border-box}
body{margin:0;background:var(--bg);color:var(--fg);
font:15px/1.5 system-ui,-apple-system,"Segoe UI",Roboto,"Helvetica Neue","DejaVu Sans",Arial,sans-serif}
.page{max-width:1200px;margin:0 auto;padding:28px 24px}
.card{background:var(--card);border:1px solid var(--line);border-radius:12px;padding:20px 24px;
margin-bottom:20px;box-shadow:0 1px 3px rgba(31,35,40,.06)}
.brand{font-weight:800;color:var(--accent);letter-spacing:.02em}
.brand span{color:var(--muted);font-weight:500}
h1{font-size:22px;margin:2px 0 16px;font-weight:650}
h2{font-size:19px;margin:0 0 4px}
h3{font-size:12px;text-transform:uppercase;letter-spacing:.07em;color:var(--muted);margin:18px 0 8px}
code,.num,.sha{font-family:var(--mono);font-size:13px}
a{color:var(--accent)}
.muted{color:var(--muted)}
)css";
}

// The verdict banner, the metadata list and the verdict badges and tags.
std::string_view banner_style() {
  return R"css(.banner{display:flex;gap:16px;align-items:center;padding:14px 18px;border-radius:10px;
margin-bottom:18px;border:1px solid var(--line)}
.big-badge{font-weight:800;text-transform:uppercase;letter-spacing:.08em;color:#fff;
padding:8px 16px;border-radius:8px;font-size:15px;white-space:nowrap;background:var(--muted)}
.headline{font-weight:700;font-size:18px}
.detail{color:var(--muted)}
.banner.gate-pass{background:var(--pass-bg);border-color:#aceebb}
.banner.gate-warn{background:var(--warn-bg);border-color:#eac54f}
.banner.gate-fail{background:var(--fail-bg);border-color:#ffcecb}
.banner.gate-unmeasured{background:var(--unm-bg);border-color:#e3c8fb}
.gate-pass .big-badge{background:var(--pass)}.gate-warn .big-badge{background:var(--warn)}
.gate-fail .big-badge{background:var(--fail)}.gate-unmeasured .big-badge{background:var(--unm)}
dl.meta{display:grid;grid-template-columns:100px 1fr;gap:6px 18px;margin:0;font-size:14px}
dl.meta dt{color:var(--muted)}dl.meta dd{margin:0}
.subject{font-weight:600}
.override{font-size:13px;color:var(--muted)}
.badge{display:inline-block;padding:2px 10px;border-radius:999px;font-size:11px;font-weight:800;
text-transform:uppercase;letter-spacing:.06em;white-space:nowrap}
.badge.gate-pass{background:var(--pass-bg);color:var(--pass)}
.badge.gate-warn{background:var(--warn-bg);color:var(--warn)}
.badge.gate-fail{background:var(--fail);color:#fff}
.badge.gate-unmeasured{background:var(--unm-bg);color:var(--unm)}
.tag{display:inline-block;padding:1px 8px;border-radius:6px;font-size:12px;font-family:var(--mono);
border:1px solid var(--line);color:var(--muted);background:#f6f8fa}
.tag.speed-REGRESSED,.tag.v-fail{color:var(--fail);border-color:#ffcecb;background:var(--fail-bg)}
.tag.speed-IMPROVED{color:var(--pass);border-color:#aceebb;background:var(--pass-bg)}
.tag.speed-INCONCLUSIVE,.tag.v-warn,.tag.v-inconclusive{color:var(--warn);border-color:#eac54f;background:var(--warn-bg)}
.tag.speed-FAILED,.tag.v-error{color:var(--unm);border-color:#e3c8fb;background:var(--unm-bg)}
.verdict{font-weight:700;font-size:13px}
.v-pass{color:var(--pass)}.v-warn,.v-inconclusive{color:var(--warn)}.v-missing{color:var(--muted);font-weight:400}.v-fail{color:var(--fail)}.v-error{color:var(--unm)}
)css";
}

// Tables and the summary counts of the overview.
std::string_view tables_style() {
  return R"css(table{border-collapse:collapse;width:100%}
th{text-align:left;font-size:11px;text-transform:uppercase;letter-spacing:.06em;color:var(--muted);
font-weight:700;border-bottom:1px solid var(--line);padding:6px 10px}
td{padding:7px 10px;border-bottom:1px solid var(--soft);vertical-align:middle}
tbody tr:last-child td{border-bottom:0}
table.scenes td:first-child a{font-weight:650;text-decoration:none}
table.scenes tr.gate-fail td:first-child{box-shadow:inset 3px 0 var(--fail)}
table.scenes tr.gate-unmeasured td:first-child{box-shadow:inset 3px 0 var(--unm)}
table.scenes tr.gate-warn td:first-child{box-shadow:inset 3px 0 var(--warn)}
.counts{display:flex;flex-wrap:wrap;gap:10px;margin:8px 0 14px}
.count{padding:3px 12px;border-radius:8px;background:#f6f8fa;color:var(--muted);font-size:14px}
.count b{font-size:17px;margin-right:3px;color:var(--fg)}
.count.gate-fail b{color:var(--fail)}.count.gate-warn b{color:var(--warn)}
.count.gate-pass b{color:var(--pass)}.count.gate-unmeasured b{color:var(--unm)}
)css";
}

// One scene's card: its coloured edge, the reasons list and the two-column body.
std::string_view scenes_style() {
  return R"css(.scene{border-left:6px solid var(--line)}
.scene.gate-pass{border-left-color:var(--pass)}.scene.gate-warn{border-left-color:var(--warn)}
.scene.gate-fail{border-left-color:var(--fail)}.scene.gate-unmeasured{border-left-color:var(--unm)}
.scene-head{display:flex;align-items:center;gap:10px;flex-wrap:wrap}
.scene-head h2{margin:0}.scene-head h2 a{color:inherit;text-decoration:none}
.spec{margin-left:auto;color:var(--muted);font-size:13px}
.reasons{margin:14px 0 0;padding:10px 14px 10px 30px;border-radius:8px;font-family:var(--mono);
font-size:12.5px;background:#f6f8fa}
.reasons li+li{margin-top:4px}
.gate-fail .reasons{background:var(--fail-bg)}.gate-warn .reasons{background:var(--warn-bg)}
.gate-unmeasured .reasons{background:var(--unm-bg)}
.scene-body{display:grid;grid-template-columns:minmax(0,460px) minmax(0,1fr);gap:28px}
@media (max-width:960px){.scene-body{grid-template-columns:1fr}}
.facts{color:var(--muted);font-size:13px;margin:6px 0 0}
.failure{background:var(--unm-bg);padding:10px 14px;border-radius:8px;font-size:14px;margin-bottom:8px}
)css";
}

// The image gallery: checkered frames for transparency, the swap-on-hover outline.
std::string_view images_style() {
  return R"css(.gallery{display:flex;flex-wrap:wrap;gap:14px}
.shot{margin:0;width:168px}
.frame{border:1px solid var(--line);border-radius:8px;overflow:hidden;line-height:0;
background:repeating-conic-gradient(#e9ecef 0 25%,#fff 0 50%) 0 0/14px 14px}
.frame img{width:100%;height:auto;display:block;cursor:crosshair}
.evidence .frame img{image-rendering:pixelated}
.shot[data-swapped] .frame{outline:3px solid var(--accent);outline-offset:-3px}
.evidence .frame{background:#000;border-color:#444}
figcaption{font-size:12px;color:var(--muted);margin-top:5px;display:flex;justify-content:space-between;gap:6px}
.who{font-weight:650;color:var(--fg)}
.hint{display:none}
body[data-js=ready] .hint{display:inline}
.no-image{line-height:1.4;padding:26px 10px;font-size:12px;color:var(--muted);text-align:center;
background:#fff;word-break:break-all}
table.metrics{margin-top:18px;font-size:13px}
)css";
}

// The SVG plots of a scene's ratio and of the scaling fits.
std::string_view plots_style() {
  return R"css(svg.plot{display:block;max-width:100%;height:auto;margin:2px 0 4px;overflow:visible}
.svg-axis{stroke:#8c959f;stroke-width:1}
.svg-grid{stroke:#eaeef2;stroke-width:1}
.svg-tick{font-size:11px;fill:var(--muted)}
.svg-label{font-size:12px;fill:var(--fg);font-weight:650}
.svg-value{font-size:12px;fill:var(--fg);font-family:var(--mono)}
.svg-note{font-size:10px;fill:var(--pass)}
.svg-interval{font-size:10px;fill:var(--muted);font-family:var(--mono)}
.mark .ci{stroke-width:5;stroke-linecap:round;opacity:.35}
.mark .cap{stroke-width:1.5}
.mark circle{stroke:#fff;stroke-width:1.5}
.mark.gate-pass{stroke:var(--pass);fill:var(--pass)}.mark.gate-warn{stroke:var(--warn);fill:var(--warn)}
.mark.gate-fail{stroke:var(--fail);fill:var(--fail)}.mark.gate-unmeasured{stroke:var(--unm);fill:var(--unm)}
.mark.role-base{stroke:#6e7781;fill:#6e7781}.mark.role-tracer{stroke:var(--accent);fill:var(--accent)}
.band{fill:var(--pass-bg)}
.zero{stroke:#8c959f;stroke-dasharray:3 3}
.scl-fit{stroke-width:2;fill:none}
.scl-baseline{stroke:#6e7781;fill:#6e7781}.scl-tracer,.scl-head{stroke:var(--accent);fill:var(--accent)}
.scl-base{stroke:#bf8700;fill:#bf8700}.scl-head .scl-fit{stroke-dasharray:6 3}
.scaling-plot circle{stroke:#fff;stroke-width:1}.scaling-plot text{stroke:none}
ul.scaling-fits{font-size:13px;margin:4px 0 14px;padding-left:18px}
)css";
}

// The history trends (ratio and memory) and the page's footer.
std::string_view trends_style() {
  return R"css(.trend-band{fill:#ddf4ff}
.trend-line{fill:none;stroke:var(--accent);stroke-width:2}
.trend-point{fill:var(--accent);stroke:#fff;stroke-width:1.5}
.trend-point.marked{fill:#0550ae;stroke-width:2}
.trend-point.flagged{fill:var(--fail)}
.memory-plot .trend-line{stroke:#8250df}
.memory-plot .trend-point{fill:#8250df}
.memory-plot .trend-point.marked{fill:#6639ba}
.memory-plot .trend-mark{fill:#6639ba}
.memory-plot .trend-point.flagged{fill:var(--fail)}
.trend-pair{display:flex;flex-wrap:wrap;gap:12px}
.trend-pair figure{margin:0;flex:1 1 0;min-width:320px}
.trend-pair svg{width:100%;height:auto}
.trend-pair figcaption{font-size:12px;color:var(--muted)}
.note{background:#fff8c5;padding:.6em;border-left:4px solid #d4a72c}
.trend-mark{font-size:11px;fill:#0550ae;font-weight:700;font-family:var(--mono)}
.sha{fill:var(--muted)}
footer{color:var(--muted);font-size:12px;text-align:center;padding:8px 0 24px}
)css";
}

}  // namespace

// In the order the page uses them; each part a few dozen rules, so a change finds its place.
std::string page_style() {
  std::string style;
  style += theme_style();
  style += banner_style();
  style += tables_style();
  style += scenes_style();
  style += images_style();
  style += plots_style();
  style += trends_style();
  return style;
}

std::string_view page_script() {
  return R"js(
(function () {
  document.querySelectorAll('img[data-swap]').forEach(function (img) {
    var other = document.getElementById(img.dataset.swap);
    var figure = img.closest('figure');
    if (!other || !figure) return;
    var who = figure.querySelector('.who');
    var own = img.getAttribute('src');
    var label = who.textContent;
    function show() {
      img.setAttribute('src', other.getAttribute('src'));
      who.textContent = img.dataset.swapLabel;
      figure.setAttribute('data-swapped', '');
    }
    function hide() {
      img.setAttribute('src', own);
      who.textContent = label;
      figure.removeAttribute('data-swapped');
    }
    img.addEventListener('mouseenter', show);
    img.addEventListener('mouseleave', hide);
    img.addEventListener('touchstart', function (event) {
      if (figure.hasAttribute('data-swapped')) { hide(); } else { show(); }
      event.preventDefault();
    }, {passive: false});
  });
  document.body.dataset.js = 'ready';
})();
)js";
}

}  // namespace raygate::report::html
