package org.miron.cli.monitor;

/**
 * The live page ({@link MonitorPage}) with a time slider on top of its side panel: the instant
 * shown ({@code #replay-at}), the adaptations as marks on the slider ({@code button.replay-mark}
 * with {@code data-at}, a click goes there) and the last decision by then
 * ({@code #replay-decision}, its {@code data-seq}, each changed varpoint with its value and the
 * engine's reason). Moving the slider asks the server to seek there; the live page's script then
 * draws the snapshot it gets, as it draws a live one.
 */
final class ReplayPage {
    private ReplayPage() {
    }

    static String html(String livePage, long durationMillis, String marks) {
        String panel = """
                <section id="replay"><h3>Replay</h3>
                <input type="range" id="replay-time" min="0" max="%1$d" value="0" step="1" list="replay-ticks" style="width:100%%">
                <datalist id="replay-ticks"></datalist>
                <div id="replay-marks" style="position:relative;height:14px"></div>
                <div><span id="replay-at">0.000 s</span> of %2$s s</div>
                <h3>Decision</h3><div id="replay-decision" style="font-size:13px">none yet</div></section>
                """.formatted(durationMillis, seconds(durationMillis));
        String script = """
                <script>
                const REPLAY_MARKS=%1$s;const REPLAY_END=%2$d;
                const slider=document.getElementById('replay-time');
                function replayShow(s){document.getElementById('replay-at').textContent=(s.at/1000).toFixed(3)+' s';
                  const d=document.getElementById('replay-decision');d.replaceChildren();
                  if(!s.decision){d.textContent='none yet';delete d.dataset.seq;return;}
                  d.dataset.seq=s.decision.seq;
                  const head=document.createElement('div');head.textContent='#'+s.decision.seq+' ('+(s.decision.outcome||'')+')';d.appendChild(head);
                  (s.decision.changed||[]).forEach(vp=>{const line=document.createElement('div');line.className='replay-change';line.dataset.name=vp;
                    const why=((s.decision.why||{})[vp]||{}).because;
                    line.textContent=vp+' = '+JSON.stringify((s.decision.decisions||{})[vp]).replace(/^"|"$/g,'')+(why?': '+why:'');d.appendChild(line);});}
                let replayPending=null,replayBusy=false;
                function replaySeek(ms){replayPending=ms;if(replayBusy)return;replayBusy=true;const at=replayPending;replayPending=null;
                  fetch('seek?at='+at).then(r=>r.json()).then(s=>{replayShow(s);}).finally(()=>{replayBusy=false;
                    if(replayPending!==null)replaySeek(replayPending);});}
                slider.addEventListener('input',()=>replaySeek(slider.value));
                const ticks=document.getElementById('replay-ticks'),strip=document.getElementById('replay-marks');
                REPLAY_MARKS.forEach(m=>{const o=document.createElement('option');o.value=m.at;ticks.appendChild(o);
                  const b=document.createElement('button');b.className='replay-mark';b.dataset.at=m.at;
                  b.title=(m.at/1000).toFixed(3)+' s: '+Object.entries(m.changed).map(([k,v])=>k+' = '+v).join(', ');
                  b.style.cssText='position:absolute;top:0;width:8px;height:12px;padding:0;border:0;background:#7c3aed;cursor:pointer;left:calc('+(REPLAY_END?100*m.at/REPLAY_END:0)+'%% - 4px)';
                  b.addEventListener('click',()=>{slider.value=m.at;replaySeek(m.at);});strip.appendChild(b);});
                fetch('state?at=0').then(r=>r.json()).then(replayShow);
                </script>
                """.formatted(marks.replace("</", "<\\/"), durationMillis);
        String page = livePage.contains("<aside>") ? livePage.replaceFirst("<aside>", "<aside>" + java.util.regex.Matcher.quoteReplacement(panel))
                : livePage.replace("</body>", panel + "</body>");
        int end = page.lastIndexOf("</body>");
        return page.substring(0, end) + script + page.substring(end);
    }

    private static String seconds(long millis) {
        return String.format(java.util.Locale.ROOT, "%.3f", millis / 1000.0);
    }
}
