package org.miron.cli.monitor;

/**
 * The live page's debugging section (docs/diagrams.md, "Debugging on the live page"): click a node
 * to select it, then break before or after its tick, force its result, clear; continue and step the
 * paused tree; the blackboards; on a variant Switch, the decision that chose its branch and why;
 * search nodes by name; fold SubTrees. The requests go to {@link DebugRoutes}, the state comes as
 * {@code debug} events (and {@code explanation} events from the bus). Read from the DOM by tests:
 * {@code #debug-status}, {@code #debug-message}, {@code #blackboard tr[data-name]}, node classes
 * {@code selected}, {@code breakpoint}, {@code forced}, {@code paused}, {@code match},
 * {@code folded} and {@code folded-away}.
 */
final class DebugPanel {
    private DebugPanel() {
    }

    static final String CSS = """
            #debug{border:1px solid #d0d7de;border-radius:6px;padding:6px 8px;margin-bottom:1em;font-size:13px;max-width:24em}
            #debug button{font-size:12px;margin:2px 2px 2px 0}#debug-status.paused{color:#dc2626;font-weight:bold}
            #debug-message{color:#dc2626;min-height:1em}#debug-switch{color:#c2410c}
            #tree g.node{cursor:pointer}#tree g.folded-away,#tree path.folded-away{display:none}
            svg.miron-bt .selected>.shape{stroke:#2563eb;stroke-width:3;stroke-dasharray:none}
            svg.miron-bt .breakpoint>.shape{stroke:#dc2626;stroke-width:4;stroke-dasharray:3 2}
            svg.miron-bt .forced>.shape{stroke:#7c3aed;stroke-width:4;stroke-dasharray:8 3}
            svg.miron-bt .paused>.shape{stroke:#dc2626;stroke-width:6;fill:#fecaca}
            svg.miron-bt .match>.shape{stroke:#eab308;stroke-width:6}
            svg.miron-bt .folded>.shape{stroke-width:4;stroke-dasharray:1 3}
            """;

    static final String HTML = """
            <section id="debug">
            <h3>Debug</h3>
            <div id="debug-status">not attached</div>
            <div><button id="debug-continue">Continue</button><button id="debug-step" title="run until just before the root's next tick">Step</button>
            <button id="debug-clear-all">Clear all</button></div>
            <div id="debug-node">click a node</div>
            <div id="debug-node-actions" hidden>
            <label><input type="checkbox" id="debug-once"> once</label><br>
            <button id="debug-break-pre">Break before</button><button id="debug-break-post">Break after</button><br>
            <button id="debug-force-SUCCESS">Force SUCCESS</button><button id="debug-force-FAILURE">Force FAILURE</button>
            <button id="debug-force-SKIPPED">Force SKIPPED</button><br>
            <button id="debug-clear">Clear</button><button id="debug-fold" hidden>Fold</button>
            </div>
            <div id="debug-switch"></div>
            <div id="debug-message"></div>
            <h4>Hooks</h4><table id="hooks"><tbody></tbody></table>
            <h4>Blackboard</h4><table id="blackboard"><tbody></tbody></table>
            </section>
            <section id="search-box"><h3>Search</h3><input id="search" type="search" placeholder="node name"> <span id="search-count"></span>
            <div><button id="fold-all">Fold all SubTrees</button><button id="unfold-all">Unfold all</button></div></section>
            <h3>Decisions</h3><table id="explanations"><tbody></tbody></table>
            """;

    static final String SCRIPT = """
            const debug={selected:null,state:null,explanations:{}};
            function nodeName(g){const t=g.querySelector('.label-title');return (t?t.textContent:g.textContent).trim();}
            function $(id){return document.getElementById(id);}
            function debugRequest(action,body){$('debug-message').textContent='';
              return fetch('debug/'+action,{method:'POST',headers:{'Content-Type':'application/json'},body:JSON.stringify(body||{})})
                .then(r=>r.text().then(t=>{if(!r.ok){$('debug-message').textContent=t;return null;}const s=JSON.parse(t);showDebug(s);return s;}))
                .catch(e=>{$('debug-message').textContent='the monitor does not answer: '+e;return null;});}
            function selectNode(id){document.querySelectorAll('#tree g.selected').forEach(g=>g.classList.remove('selected'));
              debug.selected=id;const g=node(id);if(g)g.classList.add('selected');
              $('debug-node').textContent=g?nodeName(g)+' ('+id+')':'click a node';$('debug-node-actions').hidden=!g;
              $('debug-fold').hidden=!g||g.dataset.kind!=='subtree';if(g)$('debug-fold').textContent=g.classList.contains('folded')?'Unfold':'Fold';
              showSwitch();}
            function switchOf(id){return SWITCHES.find(s=>s.node===id);}
            function showSwitch(){const s=debug.selected&&switchOf(debug.selected);let text='';
              if(s){const vp=s.key.replace(/_sel$/,'');const e=debug.explanations[vp];
                text=e?'variant switch of '+vp+' = '+JSON.stringify(e.value).replace(/^"|"$/g,'')+': '+(e.because||'(no explanation)')
                  :'variant switch of '+vp+': no decision yet';}
              $('debug-switch').textContent=text;}
            function explanation(e){debug.explanations[e.varpoint]=e;
              const v=JSON.stringify(e.value).replace(/^"|"$/g,'');row('explanations',e.varpoint,v+(e.because?': '+e.because:''));showSwitch();}
            function showDebug(s){if(debug.state&&s.revision!==undefined&&s.revision<debug.state.revision)return; // an older reply
              debug.state=s;const status=$('debug-status');
              status.className=s.paused?'paused':'';
              status.textContent=!s.attached?s.message:s.paused?'paused before '+s.paused.name+' ('+s.paused.node+')'+(s.stepping?', stepping':''):'running ('+s.message+')';
              ['breakpoint','forced','paused'].forEach(c=>document.querySelectorAll('#tree g.'+c).forEach(g=>g.classList.remove(c)));
              const hooks=document.querySelector('#hooks tbody');hooks.replaceChildren();
              (s.hooks||[]).forEach(h=>{const g=node(h.node);if(g)g.classList.add(h.mode==='BREAKPOINT'?'breakpoint':'forced');
                const tr=document.createElement('tr');tr.dataset.name=h.node;
                [h.name,h.step?'step':h.mode==='BREAKPOINT'?'break '+(h.position==='PRE'?'before':'after'):'force '+h.status,h.once?'once':'always']
                  .forEach(t=>{const td=document.createElement('td');td.textContent=t;tr.appendChild(td);});hooks.appendChild(tr);});
              if(s.paused){const g=node(s.paused.node);if(g){g.classList.add('paused');}}
              const bb=document.querySelector('#blackboard tbody');bb.replaceChildren();
              Object.entries(s.blackboards||{}).forEach(([tree,entries])=>Object.entries(entries||{}).forEach(([k,v])=>{
                row('blackboard',(tree?tree+'/':'')+k,v);}));}
            function loadDebug(){fetch('debug/state').then(r=>r.ok?r.json():r.text().then(t=>({attached:false,message:t,hooks:[]})))
              .then(showDebug).catch(()=>{});}
            function descendants(id){return Array.from(document.querySelectorAll('#tree g[data-id]')).filter(g=>g.dataset.id.startsWith(id+'.'));}
            function fold(id,on){const g=node(id);if(!g)return;g.classList.toggle('folded',on);
              const hidden=new Set(descendants(id).map(d=>d.dataset.id));
              descendants(id).forEach(d=>d.classList.toggle('folded-away',on));
              document.querySelectorAll('#tree path.edge').forEach(p=>{if(hidden.has(p.dataset.target)||hidden.has(p.dataset.source))p.classList.toggle('folded-away',on);});
              if(!on)document.querySelectorAll('#tree g.folded').forEach(f=>{if(f.dataset.id.startsWith(id+'.'))fold(f.dataset.id,true);});}
            function search(text){const q=text.trim().toLowerCase();let n=0,first=null;
              document.querySelectorAll('#tree g[data-id]').forEach(g=>{const m=q!==''&&nodeName(g).toLowerCase().includes(q);
                g.classList.toggle('match',m);if(m){n++;if(!first)first=g;}});
              $('search-count').textContent=q?n+' found':'';if(first&&first.scrollIntoView)first.scrollIntoView({block:'center',inline:'center'});}
            document.querySelectorAll('#tree g[data-id]').forEach(g=>g.addEventListener('click',e=>{e.stopPropagation();selectNode(g.dataset.id);}));
            $('debug-continue').onclick=()=>debugRequest('continue');
            $('debug-step').onclick=()=>debugRequest('step');
            $('debug-clear-all').onclick=()=>debugRequest('clear-all');
            $('debug-break-pre').onclick=()=>debugRequest('breakpoint',{node:debug.selected,position:'PRE',once:$('debug-once').checked});
            $('debug-break-post').onclick=()=>debugRequest('breakpoint',{node:debug.selected,position:'POST',once:$('debug-once').checked});
            ['SUCCESS','FAILURE','SKIPPED'].forEach(st=>$('debug-force-'+st).onclick=()=>debugRequest('force',{node:debug.selected,status:st,once:$('debug-once').checked}));
            $('debug-clear').onclick=()=>debugRequest('clear',{node:debug.selected});
            $('debug-fold').onclick=()=>{const g=node(debug.selected);if(g){fold(debug.selected,!g.classList.contains('folded'));selectNode(debug.selected);}};
            $('fold-all').onclick=()=>document.querySelectorAll('#tree g[data-kind="subtree"]').forEach(g=>fold(g.dataset.id,true));
            $('unfold-all').onclick=()=>document.querySelectorAll('#tree g.folded').forEach(g=>fold(g.dataset.id,false));
            $('search').addEventListener('input',e=>search(e.target.value));
            events.addEventListener('open',()=>{debug.state=null;loadDebug();}); // maybe a new monitor: its revisions start again
            events.addEventListener('debug',e=>showDebug(JSON.parse(e.data)));
            events.addEventListener('explanation',e=>explanation(JSON.parse(e.data)));
            events.addEventListener('snapshot',e=>Object.values(JSON.parse(e.data).explanations||{}).forEach(explanation));
            """;
}
