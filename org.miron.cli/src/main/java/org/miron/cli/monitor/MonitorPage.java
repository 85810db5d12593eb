package org.miron.cli.monitor;

import org.miron.diagram.SvgWriter;

/**
 * The live page: the tree as it runs (the SVG of org.miron.diagram, nodes numbered as the executor
 * numbers its status messages), coloured by status as events arrive, and beside it the variation
 * points' values and the metrics. Plain HTML and a few lines of script (EventSource), no framework.
 * Everything the page shows can be read from its DOM: {@code g[data-id]} nodes carry a
 * {@code status-<status>} class, the tables' rows a {@code data-name}. The debugging section
 * (breakpoints, forced results, blackboard, search, fold) is {@link DebugPanel}'s.
 */
public final class MonitorPage {
    private MonitorPage() {
    }

    /**
     * The page for a tree whose SVG is {@code svg}; {@code switches} (JSON: [{node, key, cases,
     * children}]) are the variant Switches, whose running branch the page outlines as varpoint
     * values arrive (the weaver's Switch over {@code {vp_sel}} follows varpoint {@code vp}).
     */
    public static String html(String title, String svg, String switches) {
        return """
                <!DOCTYPE html>
                <html lang="en"><head><meta charset="utf-8"><title>%1$s</title>
                <style>
                body{font-family:sans-serif;margin:1em;color:#1d232a;background:#fff;display:flex;gap:1.5em;align-items:flex-start}
                @media (prefers-color-scheme:dark){body{color:#e6edf3;background:#0d1117}td,th{border-color:#30363d!important}}
                #tree{overflow:auto;max-width:75vw;max-height:92vh;border:1px solid #d0d7de;border-radius:6px}
                aside{min-width:16em}table{border-collapse:collapse;margin-bottom:1em}
                td,th{border:1px solid #d0d7de;padding:3px 8px;text-align:left;font-size:13px}
                #connection{font-size:13px;margin-bottom:1em}.off{color:#dc2626}.on{color:#16a34a}
                .legend span{display:inline-block;padding:0 6px;margin:2px;border:3px solid;border-radius:4px;font-size:12px}
                %2$s
                %5$s</style></head><body>
                <div id="tree">%3$s</div>
                <aside>
                <h2>%1$s</h2>
                <div id="connection" class="off">connecting…</div>
                <div class="legend"><span style="border-color:#f59e0b">running</span><span style="border-color:#16a34a">success</span>
                <span style="border-color:#dc2626">failure</span><span style="border-color:#9ca3af">skipped</span></div>
                %6$s
                <h3>Variation points</h3><table id="varpoints"><tbody></tbody></table>
                <h3>Metrics</h3><table id="metrics"><tbody></tbody></table>
                <h3>Requirements</h3><table id="requirements"><tbody></tbody></table>
                <div id="tree-info"></div>
                </aside>
                <script>
                const STATUSES=['running','success','failure','skipped'];
                const SWITCHES=%4$s;
                function highlight(vp,value){SWITCHES.filter(s=>s.key===vp+'_sel').forEach(s=>{
                  let active=s.cases.indexOf(String(value));if(active<0)active=s.children.length-1;
                  s.children.forEach((child,i)=>document.querySelectorAll('#tree g[data-id]').forEach(g=>{
                    const id=g.dataset.id;if(id!==child&&!id.startsWith(child+'.'))return;
                    g.classList.toggle('active',i===active&&id===child);g.classList.toggle('inactive',i!==active);}));});}
                function node(id){return document.querySelector('#tree g[data-id="'+CSS.escape(id)+'"]');}
                function setStatus(id,to){const g=node(id);if(!g)return;STATUSES.forEach(s=>g.classList.remove('status-'+s));
                  const s=String(to).toLowerCase();if(STATUSES.includes(s))g.classList.add('status-'+s);}
                function clearStatuses(){document.querySelectorAll('#tree g[data-id]').forEach(g=>STATUSES.forEach(s=>g.classList.remove('status-'+s)));}
                function row(table,name,value){const body=document.querySelector('#'+table+' tbody');
                  let tr=body.querySelector('tr[data-name="'+CSS.escape(name)+'"]');
                  if(!tr){tr=document.createElement('tr');tr.dataset.name=name;tr.appendChild(document.createElement('th'));
                    tr.appendChild(document.createElement('td'));tr.firstChild.textContent=name;body.appendChild(tr);}
                  tr.lastChild.textContent=typeof value==='number'?(Math.round(value*1000)/1000):JSON.stringify(value).replace(/^"|"$/g,'');}
                function requirement(m){const body=document.querySelector('#requirements tbody');
                  const tr=document.createElement('tr');tr.className=m.verdict;
                  const values=Object.entries(m.values||{}).map(([n,v])=>n+' = '+JSON.stringify(v).replace(/^"|"$/g,'')).join(', ');
                  [m.time.toFixed(1)+' s',m.name,m.verdict==='met'?'met again':m.verdict+(values?': '+values:'')].forEach(t=>{
                    const td=document.createElement('td');td.textContent=t;tr.appendChild(td);});
                  if(m.verdict==='violated')tr.style.color='#dc2626';
                  body.insertBefore(tr,body.firstChild);while(body.children.length>20)body.removeChild(body.lastChild);}
                const events=new EventSource('events');
                const connection=document.getElementById('connection');
                events.onopen=()=>{connection.textContent='connected';connection.className='on';};
                events.onerror=()=>{connection.textContent='reconnecting…';connection.className='off';};
                events.addEventListener('snapshot',e=>{const s=JSON.parse(e.data);clearStatuses();
                  Object.entries(s.statuses).forEach(([id,to])=>setStatus(id,to));
                  Object.entries(s.varpoints).forEach(([n,v])=>{row('varpoints',n,v);highlight(n,v);});
                  Object.entries(s.metrics).forEach(([n,v])=>row('metrics',n,v));
                  document.querySelector('#requirements tbody').replaceChildren();(s.requirements||[]).forEach(requirement);
                  document.getElementById('tree-info').textContent=s.tree?'tree '+s.tree:'no executor yet';});
                events.addEventListener('reset',e=>{clearStatuses();const m=JSON.parse(e.data);
                  document.getElementById('tree-info').textContent='tree '+m.tree+' (started '+new Date(m.time).toLocaleTimeString()+')';});
                events.addEventListener('status',e=>{const m=JSON.parse(e.data);setStatus(m.node,m.to);});
                events.addEventListener('varpoint',e=>{const m=JSON.parse(e.data);row('varpoints',m.name,m.value);highlight(m.name,m.value);});
                events.addEventListener('requirement',e=>requirement(JSON.parse(e.data)));
                events.addEventListener('metric',e=>{const m=JSON.parse(e.data);row('metrics',m.name,m.value);});
                </script>
                <script>
                %7$s</script>
                </body></html>
                """.formatted(escape(title), SvgWriter.STYLE, svg.replace("<style>" + SvgWriter.STYLE + "</style>", ""),
                        switches.replace("</", "<\\/"), DebugPanel.CSS, DebugPanel.HTML, DebugPanel.SCRIPT);
    }

    static String escape(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
