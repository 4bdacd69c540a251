(()=>{var xu=Object.create;var Pc=Object.defineProperty;var bu=Object.getOwnPropertyDescriptor;var Su=Object.getOwnPropertyNames;var Mu=Object.getPrototypeOf,wu=Object.prototype.hasOwnProperty;var js=(i,e)=>()=>(e||i((e={exports:{}}).exports,e),e.exports);var Eu=(i,e,t,n)=>{if(e&&typeof e=="object"||typeof e=="function")for(let r of Su(e))!wu.call(i,r)&&r!==t&&Pc(i,r,{get:()=>e[r],enumerable:!(n=bu(e,r))||n.enumerable});return i};var dr=(i,e,t)=>(t=i!=null?xu(Mu(i)):{},Eu(e||!i||!i.__esModule?Pc(t,"default",{value:i,enumerable:!0}):t,i));var Lc=js((Js,Qs)=>{(function(i,e){typeof Js=="object"&&typeof Qs<"u"?Qs.exports=e():typeof define=="function"&&define.amd?define(e):(i=typeof globalThis<"u"?globalThis:i||self).graphology=e()})(Js,function(){"use strict";function i(x){return i=typeof Symbol=="function"&&typeof Symbol.iterator=="symbol"?function(w){return typeof w}:function(w){return w&&typeof Symbol=="function"&&w.constructor===Symbol&&w!==Symbol.prototype?"symbol":typeof w},i(x)}function e(x,w){x.prototype=Object.create(w.prototype),x.prototype.constructor=x,n(x,w)}function t(x){return t=Object.setPrototypeOf?Object.getPrototypeOf.bind():function(w){return w.__proto__||Object.getPrototypeOf(w)},t(x)}function n(x,w){return n=Object.setPrototypeOf?Object.setPrototypeOf.bind():function(b,u){return b.__proto__=u,b},n(x,w)}function r(){if(typeof Reflect>"u"||!Reflect.construct||Reflect.construct.sham)return!1;if(typeof Proxy=="function")return!0;try{return Boolean.prototype.valueOf.call(Reflect.construct(Boolean,[],function(){})),!0}catch{return!1}}function s(x,w,b){return s=r()?Reflect.construct.bind():function(u,c,p){var y=[null];y.push.apply(y,c);var M=new(Function.bind.apply(u,y));return p&&n(M,p.prototype),M},s.apply(null,arguments)}function a(x){var w=typeof Map=="function"?new Map:void 0;return a=function(b){if(b===null||(u=b,Function.toString.call(u).indexOf("[native code]")===-1))return b;var u;if(typeof b!="function")throw new TypeError("Super expression must either be null or a function");if(w!==void 0){if(w.has(b))return w.get(b);w.set(b,c)}function c(){return s(b,arguments,t(this).constructor)}return c.prototype=Object.create(b.prototype,{constructor:{value:c,enumerable:!1,writable:!0,configurable:!0}}),n(c,b)},a(x)}function o(x){if(x===void 0)throw new ReferenceError("this hasn't been initialised - super() hasn't been called");return x}var l=function(){for(var x=arguments[0],w=1,b=arguments.length;w<b;w++)if(arguments[w])for(var u in arguments[w])x[u]=arguments[w][u];return x};function h(x,w,b,u){var c=x._nodes.get(w),p=null;return c?p=u==="mixed"?c.out&&c.out[b]||c.undirected&&c.undirected[b]:u==="directed"?c.out&&c.out[b]:c.undirected&&c.undirected[b]:p}function d(x){return i(x)==="object"&&x!==null}function m(x){var w;for(w in x)return!1;return!0}function f(x,w,b){Object.defineProperty(x,w,{enumerable:!1,configurable:!1,writable:!0,value:b})}function v(x,w,b){var u={enumerable:!0,configurable:!0};typeof b=="function"?u.get=b:(u.value=b,u.writable=!1),Object.defineProperty(x,w,u)}function S(x){return!!d(x)&&!(x.attributes&&!Array.isArray(x.attributes))}typeof Object.assign=="function"&&(l=Object.assign);var E,_={exports:{}},g=typeof Reflect=="object"?Reflect:null,I=g&&typeof g.apply=="function"?g.apply:function(x,w,b){return Function.prototype.apply.call(x,w,b)};E=g&&typeof g.ownKeys=="function"?g.ownKeys:Object.getOwnPropertySymbols?function(x){return Object.getOwnPropertyNames(x).concat(Object.getOwnPropertySymbols(x))}:function(x){return Object.getOwnPropertyNames(x)};var P=Number.isNaN||function(x){return x!=x};function C(){C.init.call(this)}_.exports=C,_.exports.once=function(x,w){return new Promise(function(b,u){function c(y){x.removeListener(w,p),u(y)}function p(){typeof x.removeListener=="function"&&x.removeListener("error",c),b([].slice.call(arguments))}J(x,w,p,{once:!0}),w!=="error"&&function(y,M,A){typeof y.on=="function"&&J(y,"error",M,A)}(x,c,{once:!0})})},C.EventEmitter=C,C.prototype._events=void 0,C.prototype._eventsCount=0,C.prototype._maxListeners=void 0;var H=10;function U(x){if(typeof x!="function")throw new TypeError('The "listener" argument must be of type Function. Received type '+typeof x)}function N(x){return x._maxListeners===void 0?C.defaultMaxListeners:x._maxListeners}function V(x,w,b,u){var c,p,y,M;if(U(b),(p=x._events)===void 0?(p=x._events=Object.create(null),x._eventsCount=0):(p.newListener!==void 0&&(x.emit("newListener",w,b.listener?b.listener:b),p=x._events),y=p[w]),y===void 0)y=p[w]=b,++x._eventsCount;else if(typeof y=="function"?y=p[w]=u?[b,y]:[y,b]:u?y.unshift(b):y.push(b),(c=N(x))>0&&y.length>c&&!y.warned){y.warned=!0;var A=new Error("Possible EventEmitter memory leak detected. "+y.length+" "+String(w)+" listeners added. Use emitter.setMaxListeners() to increase limit");A.name="MaxListenersExceededWarning",A.emitter=x,A.type=w,A.count=y.length,M=A,console&&console.warn&&console.warn(M)}return x}function L(){if(!this.fired)return this.target.removeListener(this.type,this.wrapFn),this.fired=!0,arguments.length===0?this.listener.call(this.target):this.listener.apply(this.target,arguments)}function R(x,w,b){var u={fired:!1,wrapFn:void 0,target:x,type:w,listener:b},c=L.bind(u);return c.listener=b,u.wrapFn=c,c}function F(x,w,b){var u=x._events;if(u===void 0)return[];var c=u[w];return c===void 0?[]:typeof c=="function"?b?[c.listener||c]:[c]:b?function(p){for(var y=new Array(p.length),M=0;M<y.length;++M)y[M]=p[M].listener||p[M];return y}(c):Z(c,c.length)}function Q(x){var w=this._events;if(w!==void 0){var b=w[x];if(typeof b=="function")return 1;if(b!==void 0)return b.length}return 0}function Z(x,w){for(var b=new Array(w),u=0;u<w;++u)b[u]=x[u];return b}function J(x,w,b,u){if(typeof x.on=="function")u.once?x.once(w,b):x.on(w,b);else{if(typeof x.addEventListener!="function")throw new TypeError('The "emitter" argument must be of type EventEmitter. Received type '+typeof x);x.addEventListener(w,function c(p){u.once&&x.removeEventListener(w,c),b(p)})}}function ie(x){if(typeof x!="function")throw new Error("obliterator/iterator: expecting a function!");this.next=x}Object.defineProperty(C,"defaultMaxListeners",{enumerable:!0,get:function(){return H},set:function(x){if(typeof x!="number"||x<0||P(x))throw new RangeError('The value of "defaultMaxListeners" is out of range. It must be a non-negative number. Received '+x+".");H=x}}),C.init=function(){this._events!==void 0&&this._events!==Object.getPrototypeOf(this)._events||(this._events=Object.create(null),this._eventsCount=0),this._maxListeners=this._maxListeners||void 0},C.prototype.setMaxListeners=function(x){if(typeof x!="number"||x<0||P(x))throw new RangeError('The value of "n" is out of range. It must be a non-negative number. Received '+x+".");return this._maxListeners=x,this},C.prototype.getMaxListeners=function(){return N(this)},C.prototype.emit=function(x){for(var w=[],b=1;b<arguments.length;b++)w.push(arguments[b]);var u=x==="error",c=this._events;if(c!==void 0)u=u&&c.error===void 0;else if(!u)return!1;if(u){var p;if(w.length>0&&(p=w[0]),p instanceof Error)throw p;var y=new Error("Unhandled error."+(p?" ("+p.message+")":""));throw y.context=p,y}var M=c[x];if(M===void 0)return!1;if(typeof M=="function")I(M,this,w);else{var A=M.length,O=Z(M,A);for(b=0;b<A;++b)I(O[b],this,w)}return!0},C.prototype.addListener=function(x,w){return V(this,x,w,!1)},C.prototype.on=C.prototype.addListener,C.prototype.prependListener=function(x,w){return V(this,x,w,!0)},C.prototype.once=function(x,w){return U(w),this.on(x,R(this,x,w)),this},C.prototype.prependOnceListener=function(x,w){return U(w),this.prependListener(x,R(this,x,w)),this},C.prototype.removeListener=function(x,w){var b,u,c,p,y;if(U(w),(u=this._events)===void 0)return this;if((b=u[x])===void 0)return this;if(b===w||b.listener===w)--this._eventsCount==0?this._events=Object.create(null):(delete u[x],u.removeListener&&this.emit("removeListener",x,b.listener||w));else if(typeof b!="function"){for(c=-1,p=b.length-1;p>=0;p--)if(b[p]===w||b[p].listener===w){y=b[p].listener,c=p;break}if(c<0)return this;c===0?b.shift():function(M,A){for(;A+1<M.length;A++)M[A]=M[A+1];M.pop()}(b,c),b.length===1&&(u[x]=b[0]),u.removeListener!==void 0&&this.emit("removeListener",x,y||w)}return this},C.prototype.off=C.prototype.removeListener,C.prototype.removeAllListeners=function(x){var w,b,u;if((b=this._events)===void 0)return this;if(b.removeListener===void 0)return arguments.length===0?(this._events=Object.create(null),this._eventsCount=0):b[x]!==void 0&&(--this._eventsCount==0?this._events=Object.create(null):delete b[x]),this;if(arguments.length===0){var c,p=Object.keys(b);for(u=0;u<p.length;++u)(c=p[u])!=="removeListener"&&this.removeAllListeners(c);return this.removeAllListeners("removeListener"),this._events=Object.create(null),this._eventsCount=0,this}if(typeof(w=b[x])=="function")this.removeListener(x,w);else if(w!==void 0)for(u=w.length-1;u>=0;u--)this.removeListener(x,w[u]);return this},C.prototype.listeners=function(x){return F(this,x,!0)},C.prototype.rawListeners=function(x){return F(this,x,!1)},C.listenerCount=function(x,w){return typeof x.listenerCount=="function"?x.listenerCount(w):Q.call(x,w)},C.prototype.listenerCount=Q,C.prototype.eventNames=function(){return this._eventsCount>0?E(this._events):[]},typeof Symbol<"u"&&(ie.prototype[Symbol.iterator]=function(){return this}),ie.of=function(){var x=arguments,w=x.length,b=0;return new ie(function(){return b>=w?{done:!0}:{done:!1,value:x[b++]}})},ie.empty=function(){return new ie(function(){return{done:!0}})},ie.fromSequence=function(x){var w=0,b=x.length;return new ie(function(){return w>=b?{done:!0}:{done:!1,value:x[w++]}})},ie.is=function(x){return x instanceof ie||typeof x=="object"&&x!==null&&typeof x.next=="function"};var $=ie,ue={};ue.ARRAY_BUFFER_SUPPORT=typeof ArrayBuffer<"u",ue.SYMBOL_SUPPORT=typeof Symbol<"u";var j=$,ge=ue,_e=ge.ARRAY_BUFFER_SUPPORT,Ce=ge.SYMBOL_SUPPORT,ke=function(x){var w=function(b){return typeof b=="string"||Array.isArray(b)||_e&&ArrayBuffer.isView(b)?j.fromSequence(b):typeof b!="object"||b===null?null:Ce&&typeof b[Symbol.iterator]=="function"?b[Symbol.iterator]():typeof b.next=="function"?b:null}(x);if(!w)throw new Error("obliterator: target is not iterable nor a valid iterator.");return w},We=ke,re=function(x,w){for(var b,u=arguments.length>1?w:1/0,c=u!==1/0?new Array(u):[],p=0,y=We(x);;){if(p===u)return c;if((b=y.next()).done)return p!==w&&(c.length=p),c;c[p++]=b.value}},de=function(x){function w(b){var u;return(u=x.call(this)||this).name="GraphError",u.message=b,u}return e(w,x),w}(a(Error)),te=function(x){function w(b){var u;return(u=x.call(this,b)||this).name="InvalidArgumentsGraphError",typeof Error.captureStackTrace=="function"&&Error.captureStackTrace(o(u),w.prototype.constructor),u}return e(w,x),w}(de),W=function(x){function w(b){var u;return(u=x.call(this,b)||this).name="NotFoundGraphError",typeof Error.captureStackTrace=="function"&&Error.captureStackTrace(o(u),w.prototype.constructor),u}return e(w,x),w}(de),he=function(x){function w(b){var u;return(u=x.call(this,b)||this).name="UsageGraphError",typeof Error.captureStackTrace=="function"&&Error.captureStackTrace(o(u),w.prototype.constructor),u}return e(w,x),w}(de);function Oe(x,w){this.key=x,this.attributes=w,this.clear()}function Xe(x,w){this.key=x,this.attributes=w,this.clear()}function ut(x,w){this.key=x,this.attributes=w,this.clear()}function qe(x,w,b,u,c){this.key=w,this.attributes=c,this.undirected=x,this.source=b,this.target=u}Oe.prototype.clear=function(){this.inDegree=0,this.outDegree=0,this.undirectedDegree=0,this.undirectedLoops=0,this.directedLoops=0,this.in={},this.out={},this.undirected={}},Xe.prototype.clear=function(){this.inDegree=0,this.outDegree=0,this.directedLoops=0,this.in={},this.out={}},ut.prototype.clear=function(){this.undirectedDegree=0,this.undirectedLoops=0,this.undirected={}},qe.prototype.attach=function(){var x="out",w="in";this.undirected&&(x=w="undirected");var b=this.source.key,u=this.target.key;this.source[x][u]=this,this.undirected&&b===u||(this.target[w][b]=this)},qe.prototype.attachMulti=function(){var x="out",w="in",b=this.source.key,u=this.target.key;this.undirected&&(x=w="undirected");var c=this.source[x],p=c[u];if(p===void 0)return c[u]=this,void(this.undirected&&b===u||(this.target[w][b]=this));p.previous=this,this.next=p,c[u]=this,this.target[w][b]=this},qe.prototype.detach=function(){var x=this.source.key,w=this.target.key,b="out",u="in";this.undirected&&(b=u="undirected"),delete this.source[b][w],delete this.target[u][x]},qe.prototype.detachMulti=function(){var x=this.source.key,w=this.target.key,b="out",u="in";this.undirected&&(b=u="undirected"),this.previous===void 0?this.next===void 0?(delete this.source[b][w],delete this.target[u][x]):(this.next.previous=void 0,this.source[b][w]=this.next,this.target[u][x]=this.next):(this.previous.next=this.next,this.next!==void 0&&(this.next.previous=this.previous))};function it(x,w,b,u,c,p,y){var M,A,O,B;if(u=""+u,b===0){if(!(M=x._nodes.get(u)))throw new W("Graph.".concat(w,': could not find the "').concat(u,'" node in the graph.'));O=c,B=p}else if(b===3){if(c=""+c,!(A=x._edges.get(c)))throw new W("Graph.".concat(w,': could not find the "').concat(c,'" edge in the graph.'));var z=A.source.key,K=A.target.key;if(u===z)M=A.target;else{if(u!==K)throw new W("Graph.".concat(w,': the "').concat(u,'" node is not attached to the "').concat(c,'" edge (').concat(z,", ").concat(K,")."));M=A.source}O=p,B=y}else{if(!(A=x._edges.get(u)))throw new W("Graph.".concat(w,': could not find the "').concat(u,'" edge in the graph.'));M=b===1?A.source:A.target,O=c,B=p}return[M,O,B]}var G=[{name:function(x){return"get".concat(x,"Attribute")},attacher:function(x,w,b){x.prototype[w]=function(u,c,p){var y=it(this,w,b,u,c,p),M=y[0],A=y[1];return M.attributes[A]}}},{name:function(x){return"get".concat(x,"Attributes")},attacher:function(x,w,b){x.prototype[w]=function(u,c){return it(this,w,b,u,c)[0].attributes}}},{name:function(x){return"has".concat(x,"Attribute")},attacher:function(x,w,b){x.prototype[w]=function(u,c,p){var y=it(this,w,b,u,c,p),M=y[0],A=y[1];return M.attributes.hasOwnProperty(A)}}},{name:function(x){return"set".concat(x,"Attribute")},attacher:function(x,w,b){x.prototype[w]=function(u,c,p,y){var M=it(this,w,b,u,c,p,y),A=M[0],O=M[1],B=M[2];return A.attributes[O]=B,this.emit("nodeAttributesUpdated",{key:A.key,type:"set",attributes:A.attributes,name:O}),this}}},{name:function(x){return"update".concat(x,"Attribute")},attacher:function(x,w,b){x.prototype[w]=function(u,c,p,y){var M=it(this,w,b,u,c,p,y),A=M[0],O=M[1],B=M[2];if(typeof B!="function")throw new te("Graph.".concat(w,": updater should be a function."));var z=A.attributes,K=B(z[O]);return z[O]=K,this.emit("nodeAttributesUpdated",{key:A.key,type:"set",attributes:A.attributes,name:O}),this}}},{name:function(x){return"remove".concat(x,"Attribute")},attacher:function(x,w,b){x.prototype[w]=function(u,c,p){var y=it(this,w,b,u,c,p),M=y[0],A=y[1];return delete M.attributes[A],this.emit("nodeAttributesUpdated",{key:M.key,type:"remove",attributes:M.attributes,name:A}),this}}},{name:function(x){return"replace".concat(x,"Attributes")},attacher:function(x,w,b){x.prototype[w]=function(u,c,p){var y=it(this,w,b,u,c,p),M=y[0],A=y[1];if(!d(A))throw new te("Graph.".concat(w,": provided attributes are not a plain object."));return M.attributes=A,this.emit("nodeAttributesUpdated",{key:M.key,type:"replace",attributes:M.attributes}),this}}},{name:function(x){return"merge".concat(x,"Attributes")},attacher:function(x,w,b){x.prototype[w]=function(u,c,p){var y=it(this,w,b,u,c,p),M=y[0],A=y[1];if(!d(A))throw new te("Graph.".concat(w,": provided attributes are not a plain object."));return l(M.attributes,A),this.emit("nodeAttributesUpdated",{key:M.key,type:"merge",attributes:M.attributes,data:A}),this}}},{name:function(x){return"update".concat(x,"Attributes")},attacher:function(x,w,b){x.prototype[w]=function(u,c,p){var y=it(this,w,b,u,c,p),M=y[0],A=y[1];if(typeof A!="function")throw new te("Graph.".concat(w,": provided updater is not a function."));return M.attributes=A(M.attributes),this.emit("nodeAttributesUpdated",{key:M.key,type:"update",attributes:M.attributes}),this}}}],Ut=[{name:function(x){return"get".concat(x,"Attribute")},attacher:function(x,w,b){x.prototype[w]=function(u,c){var p;if(this.type!=="mixed"&&b!=="mixed"&&b!==this.type)throw new he("Graph.".concat(w,": cannot find this type of edges in your ").concat(this.type," graph."));if(arguments.length>2){if(this.multi)throw new he("Graph.".concat(w,": cannot use a {source,target} combo when asking about an edge's attributes in a MultiGraph since we cannot infer the one you want information about."));var y=""+u,M=""+c;if(c=arguments[2],!(p=h(this,y,M,b)))throw new W("Graph.".concat(w,': could not find an edge for the given path ("').concat(y,'" - "').concat(M,'").'))}else{if(b!=="mixed")throw new he("Graph.".concat(w,": calling this method with only a key (vs. a source and target) does not make sense since an edge with this key could have the other type."));if(u=""+u,!(p=this._edges.get(u)))throw new W("Graph.".concat(w,': could not find the "').concat(u,'" edge in the graph.'))}return p.attributes[c]}}},{name:function(x){return"get".concat(x,"Attributes")},attacher:function(x,w,b){x.prototype[w]=function(u){var c;if(this.type!=="mixed"&&b!=="mixed"&&b!==this.type)throw new he("Graph.".concat(w,": cannot find this type of edges in your ").concat(this.type," graph."));if(arguments.length>1){if(this.multi)throw new he("Graph.".concat(w,": cannot use a {source,target} combo when asking about an edge's attributes in a MultiGraph since we cannot infer the one you want information about."));var p=""+u,y=""+arguments[1];if(!(c=h(this,p,y,b)))throw new W("Graph.".concat(w,': could not find an edge for the given path ("').concat(p,'" - "').concat(y,'").'))}else{if(b!=="mixed")throw new he("Graph.".concat(w,": calling this method with only a key (vs. a source and target) does not make sense since an edge with this key could have the other type."));if(u=""+u,!(c=this._edges.get(u)))throw new W("Graph.".concat(w,': could not find the "').concat(u,'" edge in the graph.'))}return c.attributes}}},{name:function(x){return"has".concat(x,"Attribute")},attacher:function(x,w,b){x.prototype[w]=function(u,c){var p;if(this.type!=="mixed"&&b!=="mixed"&&b!==this.type)throw new he("Graph.".concat(w,": cannot find this type of edges in your ").concat(this.type," graph."));if(arguments.length>2){if(this.multi)throw new he("Graph.".concat(w,": cannot use a {source,target} combo when asking about an edge's attributes in a MultiGraph since we cannot infer the one you want information about."));var y=""+u,M=""+c;if(c=arguments[2],!(p=h(this,y,M,b)))throw new W("Graph.".concat(w,': could not find an edge for the given path ("').concat(y,'" - "').concat(M,'").'))}else{if(b!=="mixed")throw new he("Graph.".concat(w,": calling this method with only a key (vs. a source and target) does not make sense since an edge with this key could have the other type."));if(u=""+u,!(p=this._edges.get(u)))throw new W("Graph.".concat(w,': could not find the "').concat(u,'" edge in the graph.'))}return p.attributes.hasOwnProperty(c)}}},{name:function(x){return"set".concat(x,"Attribute")},attacher:function(x,w,b){x.prototype[w]=function(u,c,p){var y;if(this.type!=="mixed"&&b!=="mixed"&&b!==this.type)throw new he("Graph.".concat(w,": cannot find this type of edges in your ").concat(this.type," graph."));if(arguments.length>3){if(this.multi)throw new he("Graph.".concat(w,": cannot use a {source,target} combo when asking about an edge's attributes in a MultiGraph since we cannot infer the one you want information about."));var M=""+u,A=""+c;if(c=arguments[2],p=arguments[3],!(y=h(this,M,A,b)))throw new W("Graph.".concat(w,': could not find an edge for the given path ("').concat(M,'" - "').concat(A,'").'))}else{if(b!=="mixed")throw new he("Graph.".concat(w,": calling this method with only a key (vs. a source and target) does not make sense since an edge with this key could have the other type."));if(u=""+u,!(y=this._edges.get(u)))throw new W("Graph.".concat(w,': could not find the "').concat(u,'" edge in the graph.'))}return y.attributes[c]=p,this.emit("edgeAttributesUpdated",{key:y.key,type:"set",attributes:y.attributes,name:c}),this}}},{name:function(x){return"update".concat(x,"Attribute")},attacher:function(x,w,b){x.prototype[w]=function(u,c,p){var y;if(this.type!=="mixed"&&b!=="mixed"&&b!==this.type)throw new he("Graph.".concat(w,": cannot find this type of edges in your ").concat(this.type," graph."));if(arguments.length>3){if(this.multi)throw new he("Graph.".concat(w,": cannot use a {source,target} combo when asking about an edge's attributes in a MultiGraph since we cannot infer the one you want information about."));var M=""+u,A=""+c;if(c=arguments[2],p=arguments[3],!(y=h(this,M,A,b)))throw new W("Graph.".concat(w,': could not find an edge for the given path ("').concat(M,'" - "').concat(A,'").'))}else{if(b!=="mixed")throw new he("Graph.".concat(w,": calling this method with only a key (vs. a source and target) does not make sense since an edge with this key could have the other type."));if(u=""+u,!(y=this._edges.get(u)))throw new W("Graph.".concat(w,': could not find the "').concat(u,'" edge in the graph.'))}if(typeof p!="function")throw new te("Graph.".concat(w,": updater should be a function."));return y.attributes[c]=p(y.attributes[c]),this.emit("edgeAttributesUpdated",{key:y.key,type:"set",attributes:y.attributes,name:c}),this}}},{name:function(x){return"remove".concat(x,"Attribute")},attacher:function(x,w,b){x.prototype[w]=function(u,c){var p;if(this.type!=="mixed"&&b!=="mixed"&&b!==this.type)throw new he("Graph.".concat(w,": cannot find this type of edges in your ").concat(this.type," graph."));if(arguments.length>2){if(this.multi)throw new he("Graph.".concat(w,": cannot use a {source,target} combo when asking about an edge's attributes in a MultiGraph since we cannot infer the one you want information about."));var y=""+u,M=""+c;if(c=arguments[2],!(p=h(this,y,M,b)))throw new W("Graph.".concat(w,': could not find an edge for the given path ("').concat(y,'" - "').concat(M,'").'))}else{if(b!=="mixed")throw new he("Graph.".concat(w,": calling this method with only a key (vs. a source and target) does not make sense since an edge with this key could have the other type."));if(u=""+u,!(p=this._edges.get(u)))throw new W("Graph.".concat(w,': could not find the "').concat(u,'" edge in the graph.'))}return delete p.attributes[c],this.emit("edgeAttributesUpdated",{key:p.key,type:"remove",attributes:p.attributes,name:c}),this}}},{name:function(x){return"replace".concat(x,"Attributes")},attacher:function(x,w,b){x.prototype[w]=function(u,c){var p;if(this.type!=="mixed"&&b!=="mixed"&&b!==this.type)throw new he("Graph.".concat(w,": cannot find this type of edges in your ").concat(this.type," graph."));if(arguments.length>2){if(this.multi)throw new he("Graph.".concat(w,": cannot use a {source,target} combo when asking about an edge's attributes in a MultiGraph since we cannot infer the one you want information about."));var y=""+u,M=""+c;if(c=arguments[2],!(p=h(this,y,M,b)))throw new W("Graph.".concat(w,': could not find an edge for the given path ("').concat(y,'" - "').concat(M,'").'))}else{if(b!=="mixed")throw new he("Graph.".concat(w,": calling this method with only a key (vs. a source and target) does not make sense since an edge with this key could have the other type."));if(u=""+u,!(p=this._edges.get(u)))throw new W("Graph.".concat(w,': could not find the "').concat(u,'" edge in the graph.'))}if(!d(c))throw new te("Graph.".concat(w,": provided attributes are not a plain object."));return p.attributes=c,this.emit("edgeAttributesUpdated",{key:p.key,type:"replace",attributes:p.attributes}),this}}},{name:function(x){return"merge".concat(x,"Attributes")},attacher:function(x,w,b){x.prototype[w]=function(u,c){var p;if(this.type!=="mixed"&&b!=="mixed"&&b!==this.type)throw new he("Graph.".concat(w,": cannot find this type of edges in your ").concat(this.type," graph."));if(arguments.length>2){if(this.multi)throw new he("Graph.".concat(w,": cannot use a {source,target} combo when asking about an edge's attributes in a MultiGraph since we cannot infer the one you want information about."));var y=""+u,M=""+c;if(c=arguments[2],!(p=h(this,y,M,b)))throw new W("Graph.".concat(w,': could not find an edge for the given path ("').concat(y,'" - "').concat(M,'").'))}else{if(b!=="mixed")throw new he("Graph.".concat(w,": calling this method with only a key (vs. a source and target) does not make sense since an edge with this key could have the other type."));if(u=""+u,!(p=this._edges.get(u)))throw new W("Graph.".concat(w,': could not find the "').concat(u,'" edge in the graph.'))}if(!d(c))throw new te("Graph.".concat(w,": provided attributes are not a plain object."));return l(p.attributes,c),this.emit("edgeAttributesUpdated",{key:p.key,type:"merge",attributes:p.attributes,data:c}),this}}},{name:function(x){return"update".concat(x,"Attributes")},attacher:function(x,w,b){x.prototype[w]=function(u,c){var p;if(this.type!=="mixed"&&b!=="mixed"&&b!==this.type)throw new he("Graph.".concat(w,": cannot find this type of edges in your ").concat(this.type," graph."));if(arguments.length>2){if(this.multi)throw new he("Graph.".concat(w,": cannot use a {source,target} combo when asking about an edge's attributes in a MultiGraph since we cannot infer the one you want information about."));var y=""+u,M=""+c;if(c=arguments[2],!(p=h(this,y,M,b)))throw new W("Graph.".concat(w,': could not find an edge for the given path ("').concat(y,'" - "').concat(M,'").'))}else{if(b!=="mixed")throw new he("Graph.".concat(w,": calling this method with only a key (vs. a source and target) does not make sense since an edge with this key could have the other type."));if(u=""+u,!(p=this._edges.get(u)))throw new W("Graph.".concat(w,': could not find the "').concat(u,'" edge in the graph.'))}if(typeof c!="function")throw new te("Graph.".concat(w,": provided updater is not a function."));return p.attributes=c(p.attributes),this.emit("edgeAttributesUpdated",{key:p.key,type:"update",attributes:p.attributes}),this}}}],Ke=$,je=ke,Pe=function(){var x=arguments,w=null,b=-1;return new Ke(function(){for(var u=null;;){if(w===null){if(++b>=x.length)return{done:!0};w=je(x[b])}if((u=w.next()).done!==!0)break;w=null}return u})},ht=[{name:"edges",type:"mixed"},{name:"inEdges",type:"directed",direction:"in"},{name:"outEdges",type:"directed",direction:"out"},{name:"inboundEdges",type:"mixed",direction:"in"},{name:"outboundEdges",type:"mixed",direction:"out"},{name:"directedEdges",type:"directed"},{name:"undirectedEdges",type:"undirected"}];function De(x,w,b,u){var c=!1;for(var p in w)if(p!==u){var y=w[p];if(c=b(y.key,y.attributes,y.source.key,y.target.key,y.source.attributes,y.target.attributes,y.undirected),x&&c)return y.key}}function D(x,w,b,u){var c,p,y,M=!1;for(var A in w)if(A!==u){c=w[A];do{if(p=c.source,y=c.target,M=b(c.key,c.attributes,p.key,y.key,p.attributes,y.attributes,c.undirected),x&&M)return c.key;c=c.next}while(c!==void 0)}}function T(x,w){var b,u=Object.keys(x),c=u.length,p=0;return new $(function(){do if(b)b=b.next;else{if(p>=c)return{done:!0};var y=u[p++];if(y===w){b=void 0;continue}b=x[y]}while(!b);return{done:!1,value:{edge:b.key,attributes:b.attributes,source:b.source.key,target:b.target.key,sourceAttributes:b.source.attributes,targetAttributes:b.target.attributes,undirected:b.undirected}}})}function q(x,w,b,u){var c=w[b];if(c){var p=c.source,y=c.target;return u(c.key,c.attributes,p.key,y.key,p.attributes,y.attributes,c.undirected)&&x?c.key:void 0}}function oe(x,w,b,u){var c=w[b];if(c){var p=!1;do{if(p=u(c.key,c.attributes,c.source.key,c.target.key,c.source.attributes,c.target.attributes,c.undirected),x&&p)return c.key;c=c.next}while(c!==void 0)}}function le(x,w){var b=x[w];return b.next!==void 0?new $(function(){if(!b)return{done:!0};var u={edge:b.key,attributes:b.attributes,source:b.source.key,target:b.target.key,sourceAttributes:b.source.attributes,targetAttributes:b.target.attributes,undirected:b.undirected};return b=b.next,{done:!1,value:u}}):$.of({edge:b.key,attributes:b.attributes,source:b.source.key,target:b.target.key,sourceAttributes:b.source.attributes,targetAttributes:b.target.attributes,undirected:b.undirected})}function se(x,w){if(x.size===0)return[];if(w==="mixed"||w===x.type)return typeof Array.from=="function"?Array.from(x._edges.keys()):re(x._edges.keys(),x._edges.size);for(var b,u,c=w==="undirected"?x.undirectedSize:x.directedSize,p=new Array(c),y=w==="undirected",M=x._edges.values(),A=0;(b=M.next()).done!==!0;)(u=b.value).undirected===y&&(p[A++]=u.key);return p}function Le(x,w,b,u){if(w.size!==0){for(var c,p,y=b!=="mixed"&&b!==w.type,M=b==="undirected",A=!1,O=w._edges.values();(c=O.next()).done!==!0;)if(p=c.value,!y||p.undirected===M){var B=p,z=B.key,K=B.attributes,ne=B.source,fe=B.target;if(A=u(z,K,ne.key,fe.key,ne.attributes,fe.attributes,p.undirected),x&&A)return z}}}function be(x,w){if(x.size===0)return $.empty();var b=w!=="mixed"&&w!==x.type,u=w==="undirected",c=x._edges.values();return new $(function(){for(var p,y;;){if((p=c.next()).done)return p;if(y=p.value,!b||y.undirected===u)break}return{value:{edge:y.key,attributes:y.attributes,source:y.source.key,target:y.target.key,sourceAttributes:y.source.attributes,targetAttributes:y.target.attributes,undirected:y.undirected},done:!1}})}function Ee(x,w,b,u,c,p){var y,M=w?D:De;if(b!=="undirected"&&(u!=="out"&&(y=M(x,c.in,p),x&&y)||u!=="in"&&(y=M(x,c.out,p,u?void 0:c.key),x&&y))||b!=="directed"&&(y=M(x,c.undirected,p),x&&y))return y}function Je(x,w,b,u){var c=[];return Ee(!1,x,w,b,u,function(p){c.push(p)}),c}function me(x,w,b){var u=$.empty();return x!=="undirected"&&(w!=="out"&&b.in!==void 0&&(u=Pe(u,T(b.in))),w!=="in"&&b.out!==void 0&&(u=Pe(u,T(b.out,w?void 0:b.key)))),x!=="directed"&&b.undirected!==void 0&&(u=Pe(u,T(b.undirected))),u}function Te(x,w,b,u,c,p,y){var M,A=b?oe:q;if(w!=="undirected"&&(c.in!==void 0&&u!=="out"&&(M=A(x,c.in,p,y),x&&M)||c.out!==void 0&&u!=="in"&&(u||c.key!==p)&&(M=A(x,c.out,p,y),x&&M))||w!=="directed"&&c.undirected!==void 0&&(M=A(x,c.undirected,p,y),x&&M))return M}function Ne(x,w,b,u,c){var p=[];return Te(!1,x,w,b,u,c,function(y){p.push(y)}),p}function Ue(x,w,b,u){var c=$.empty();return x!=="undirected"&&(b.in!==void 0&&w!=="out"&&u in b.in&&(c=Pe(c,le(b.in,u))),b.out!==void 0&&w!=="in"&&u in b.out&&(w||b.key!==u)&&(c=Pe(c,le(b.out,u)))),x!=="directed"&&b.undirected!==void 0&&u in b.undirected&&(c=Pe(c,le(b.undirected,u))),c}var Ae=[{name:"neighbors",type:"mixed"},{name:"inNeighbors",type:"directed",direction:"in"},{name:"outNeighbors",type:"directed",direction:"out"},{name:"inboundNeighbors",type:"mixed",direction:"in"},{name:"outboundNeighbors",type:"mixed",direction:"out"},{name:"directedNeighbors",type:"directed"},{name:"undirectedNeighbors",type:"undirected"}];function Ze(){this.A=null,this.B=null}function Fe(x,w,b,u,c){for(var p in u){var y=u[p],M=y.source,A=y.target,O=M===b?A:M;if(!w||!w.has(O.key)){var B=c(O.key,O.attributes);if(x&&B)return O.key}}}function rt(x,w,b,u,c){if(w!=="mixed"){if(w==="undirected")return Fe(x,null,u,u.undirected,c);if(typeof b=="string")return Fe(x,null,u,u[b],c)}var p,y=new Ze;if(w!=="undirected"){if(b!=="out"){if(p=Fe(x,null,u,u.in,c),x&&p)return p;y.wrap(u.in)}if(b!=="in"){if(p=Fe(x,y,u,u.out,c),x&&p)return p;y.wrap(u.out)}}if(w!=="directed"&&(p=Fe(x,y,u,u.undirected,c),x&&p))return p}function k(x,w,b){var u=Object.keys(b),c=u.length,p=0;return new $(function(){var y=null;do{if(p>=c)return x&&x.wrap(b),{done:!0};var M=b[u[p++]],A=M.source,O=M.target;y=A===w?O:A,x&&x.has(y.key)&&(y=null)}while(y===null);return{done:!1,value:{neighbor:y.key,attributes:y.attributes}}})}function xe(x,w){var b=w.name,u=w.type,c=w.direction;x.prototype[b]=function(p){if(u!=="mixed"&&this.type!=="mixed"&&u!==this.type)return[];p=""+p;var y=this._nodes.get(p);if(y===void 0)throw new W("Graph.".concat(b,': could not find the "').concat(p,'" node in the graph.'));return function(M,A,O){if(M!=="mixed"){if(M==="undirected")return Object.keys(O.undirected);if(typeof A=="string")return Object.keys(O[A])}var B=[];return rt(!1,M,A,O,function(z){B.push(z)}),B}(u==="mixed"?this.type:u,c,y)}}function ee(x,w){var b=w.name,u=w.type,c=w.direction,p=b.slice(0,-1)+"Entries";x.prototype[p]=function(y){if(u!=="mixed"&&this.type!=="mixed"&&u!==this.type)return $.empty();y=""+y;var M=this._nodes.get(y);if(M===void 0)throw new W("Graph.".concat(p,': could not find the "').concat(y,'" node in the graph.'));return function(A,O,B){if(A!=="mixed"){if(A==="undirected")return k(null,B,B.undirected);if(typeof O=="string")return k(null,B,B[O])}var z=$.empty(),K=new Ze;return A!=="undirected"&&(O!=="out"&&(z=Pe(z,k(K,B,B.in))),O!=="in"&&(z=Pe(z,k(K,B,B.out)))),A!=="directed"&&(z=Pe(z,k(K,B,B.undirected))),z}(u==="mixed"?this.type:u,c,M)}}function ae(x,w,b,u,c){for(var p,y,M,A,O,B,z,K=u._nodes.values(),ne=u.type;(p=K.next()).done!==!0;){var fe=!1;if(y=p.value,ne!=="undirected")for(M in A=y.out){O=A[M];do{if(B=O.target,fe=!0,z=c(y.key,B.key,y.attributes,B.attributes,O.key,O.attributes,O.undirected),x&&z)return O;O=O.next}while(O)}if(ne!=="directed"){for(M in A=y.undirected)if(!(w&&y.key>M)){O=A[M];do{if((B=O.target).key!==M&&(B=O.source),fe=!0,z=c(y.key,B.key,y.attributes,B.attributes,O.key,O.attributes,O.undirected),x&&z)return O;O=O.next}while(O)}}if(b&&!fe&&(z=c(y.key,null,y.attributes,null,null,null,null),x&&z))return null}}function Me(x){if(!d(x))throw new te('Graph.import: invalid serialized node. A serialized node should be a plain object with at least a "key" property.');if(!("key"in x))throw new te("Graph.import: serialized node is missing its key.");if("attributes"in x&&(!d(x.attributes)||x.attributes===null))throw new te("Graph.import: invalid attributes. Attributes should be a plain object, null or omitted.")}function Se(x){if(!d(x))throw new te('Graph.import: invalid serialized edge. A serialized edge should be a plain object with at least a "source" & "target" property.');if(!("source"in x))throw new te("Graph.import: serialized edge is missing its source.");if(!("target"in x))throw new te("Graph.import: serialized edge is missing its target.");if("attributes"in x&&(!d(x.attributes)||x.attributes===null))throw new te("Graph.import: invalid attributes. Attributes should be a plain object, null or omitted.");if("undirected"in x&&typeof x.undirected!="boolean")throw new te("Graph.import: invalid undirectedness information. Undirected should be boolean or omitted.")}Ze.prototype.wrap=function(x){this.A===null?this.A=x:this.B===null&&(this.B=x)},Ze.prototype.has=function(x){return this.A!==null&&x in this.A||this.B!==null&&x in this.B};var Be,ft=(Be=255&Math.floor(256*Math.random()),function(){return Be++}),wt=new Set(["directed","undirected","mixed"]),nt=new Set(["domain","_events","_eventsCount","_maxListeners"]),zt={allowSelfLoops:!0,multi:!1,type:"mixed"};function Ht(x,w,b){var u=new x.NodeDataClass(w,b);return x._nodes.set(w,u),x.emit("nodeAdded",{key:w,attributes:b}),u}function or(x,w,b,u,c,p,y,M){if(!u&&x.type==="undirected")throw new he("Graph.".concat(w,": you cannot add a directed edge to an undirected graph. Use the #.addEdge or #.addUndirectedEdge instead."));if(u&&x.type==="directed")throw new he("Graph.".concat(w,": you cannot add an undirected edge to a directed graph. Use the #.addEdge or #.addDirectedEdge instead."));if(M&&!d(M))throw new te("Graph.".concat(w,': invalid attributes. Expecting an object but got "').concat(M,'"'));if(p=""+p,y=""+y,M=M||{},!x.allowSelfLoops&&p===y)throw new he("Graph.".concat(w,': source & target are the same ("').concat(p,`"), thus creating a loop explicitly forbidden by this graph 'allowSelfLoops' option set to false.`));var A=x._nodes.get(p),O=x._nodes.get(y);if(!A)throw new W("Graph.".concat(w,': source node "').concat(p,'" not found.'));if(!O)throw new W("Graph.".concat(w,': target node "').concat(y,'" not found.'));var B={key:null,undirected:u,source:p,target:y,attributes:M};if(b)c=x._edgeKeyGenerator();else if(c=""+c,x._edges.has(c))throw new he("Graph.".concat(w,': the "').concat(c,'" edge already exists in the graph.'));if(!x.multi&&(u?A.undirected[y]!==void 0:A.out[y]!==void 0))throw new he("Graph.".concat(w,': an edge linking "').concat(p,'" to "').concat(y,`" already exists. If you really want to add multiple edges linking those nodes, you should create a multi graph by using the 'multi' option.`));var z=new qe(u,c,A,O,M);x._edges.set(c,z);var K=p===y;return u?(A.undirectedDegree++,O.undirectedDegree++,K&&(A.undirectedLoops++,x._undirectedSelfLoopCount++)):(A.outDegree++,O.inDegree++,K&&(A.directedLoops++,x._directedSelfLoopCount++)),x.multi?z.attachMulti():z.attach(),u?x._undirectedSize++:x._directedSize++,B.key=c,x.emit("edgeAdded",B),c}function Nr(x,w,b,u,c,p,y,M,A){if(!u&&x.type==="undirected")throw new he("Graph.".concat(w,": you cannot merge/update a directed edge to an undirected graph. Use the #.mergeEdge/#.updateEdge or #.addUndirectedEdge instead."));if(u&&x.type==="directed")throw new he("Graph.".concat(w,": you cannot merge/update an undirected edge to a directed graph. Use the #.mergeEdge/#.updateEdge or #.addDirectedEdge instead."));if(M){if(A){if(typeof M!="function")throw new te("Graph.".concat(w,': invalid updater function. Expecting a function but got "').concat(M,'"'))}else if(!d(M))throw new te("Graph.".concat(w,': invalid attributes. Expecting an object but got "').concat(M,'"'))}var O;if(p=""+p,y=""+y,A&&(O=M,M=void 0),!x.allowSelfLoops&&p===y)throw new he("Graph.".concat(w,': source & target are the same ("').concat(p,`"), thus creating a loop explicitly forbidden by this graph 'allowSelfLoops' option set to false.`));var B,z,K=x._nodes.get(p),ne=x._nodes.get(y);if(!b&&(B=x._edges.get(c))){if(!(B.source.key===p&&B.target.key===y||u&&B.source.key===y&&B.target.key===p))throw new he("Graph.".concat(w,': inconsistency detected when attempting to merge the "').concat(c,'" edge with "').concat(p,'" source & "').concat(y,'" target vs. ("').concat(B.source.key,'", "').concat(B.target.key,'").'));z=B}if(z||x.multi||!K||(z=u?K.undirected[y]:K.out[y]),z){var fe=[z.key,!1,!1,!1];if(A?!O:!M)return fe;if(A){var pe=z.attributes;z.attributes=O(pe),x.emit("edgeAttributesUpdated",{type:"replace",key:z.key,attributes:z.attributes})}else l(z.attributes,M),x.emit("edgeAttributesUpdated",{type:"merge",key:z.key,attributes:z.attributes,data:M});return fe}M=M||{},A&&O&&(M=O(M));var Ie={key:null,undirected:u,source:p,target:y,attributes:M};if(b)c=x._edgeKeyGenerator();else if(c=""+c,x._edges.has(c))throw new he("Graph.".concat(w,': the "').concat(c,'" edge already exists in the graph.'));var ze=!1,Ge=!1;K||(K=Ht(x,p,{}),ze=!0,p===y&&(ne=K,Ge=!0)),ne||(ne=Ht(x,y,{}),Ge=!0),B=new qe(u,c,K,ne,M),x._edges.set(c,B);var at=p===y;return u?(K.undirectedDegree++,ne.undirectedDegree++,at&&(K.undirectedLoops++,x._undirectedSelfLoopCount++)):(K.outDegree++,ne.inDegree++,at&&(K.directedLoops++,x._directedSelfLoopCount++)),x.multi?B.attachMulti():B.attach(),u?x._undirectedSize++:x._directedSize++,Ie.key=c,x.emit("edgeAdded",Ie),[c,!0,ze,Ge]}function Ft(x,w){x._edges.delete(w.key);var b=w.source,u=w.target,c=w.attributes,p=w.undirected,y=b===u;p?(b.undirectedDegree--,u.undirectedDegree--,y&&(b.undirectedLoops--,x._undirectedSelfLoopCount--)):(b.outDegree--,u.inDegree--,y&&(b.directedLoops--,x._directedSelfLoopCount--)),x.multi?w.detachMulti():w.detach(),p?x._undirectedSize--:x._directedSize--,x.emit("edgeDropped",{key:w.key,attributes:c,source:b.key,target:u.key,undirected:p})}var st=function(x){function w(u){var c;if(c=x.call(this)||this,typeof(u=l({},zt,u)).multi!="boolean")throw new te(`Graph.constructor: invalid 'multi' option. Expecting a boolean but got "`.concat(u.multi,'".'));if(!wt.has(u.type))throw new te(`Graph.constructor: invalid 'type' option. Should be one of "mixed", "directed" or "undirected" but got "`.concat(u.type,'".'));if(typeof u.allowSelfLoops!="boolean")throw new te(`Graph.constructor: invalid 'allowSelfLoops' option. Expecting a boolean but got "`.concat(u.allowSelfLoops,'".'));var p=u.type==="mixed"?Oe:u.type==="directed"?Xe:ut;f(o(c),"NodeDataClass",p);var y="geid_"+ft()+"_",M=0;return f(o(c),"_attributes",{}),f(o(c),"_nodes",new Map),f(o(c),"_edges",new Map),f(o(c),"_directedSize",0),f(o(c),"_undirectedSize",0),f(o(c),"_directedSelfLoopCount",0),f(o(c),"_undirectedSelfLoopCount",0),f(o(c),"_edgeKeyGenerator",function(){var A;do A=y+M++;while(c._edges.has(A));return A}),f(o(c),"_options",u),nt.forEach(function(A){return f(o(c),A,c[A])}),v(o(c),"order",function(){return c._nodes.size}),v(o(c),"size",function(){return c._edges.size}),v(o(c),"directedSize",function(){return c._directedSize}),v(o(c),"undirectedSize",function(){return c._undirectedSize}),v(o(c),"selfLoopCount",function(){return c._directedSelfLoopCount+c._undirectedSelfLoopCount}),v(o(c),"directedSelfLoopCount",function(){return c._directedSelfLoopCount}),v(o(c),"undirectedSelfLoopCount",function(){return c._undirectedSelfLoopCount}),v(o(c),"multi",c._options.multi),v(o(c),"type",c._options.type),v(o(c),"allowSelfLoops",c._options.allowSelfLoops),v(o(c),"implementation",function(){return"graphology"}),c}e(w,x);var b=w.prototype;return b._resetInstanceCounters=function(){this._directedSize=0,this._undirectedSize=0,this._directedSelfLoopCount=0,this._undirectedSelfLoopCount=0},b.hasNode=function(u){return this._nodes.has(""+u)},b.hasDirectedEdge=function(u,c){if(this.type==="undirected")return!1;if(arguments.length===1){var p=""+u,y=this._edges.get(p);return!!y&&!y.undirected}if(arguments.length===2){u=""+u,c=""+c;var M=this._nodes.get(u);return!!M&&M.out.hasOwnProperty(c)}throw new te("Graph.hasDirectedEdge: invalid arity (".concat(arguments.length,", instead of 1 or 2). You can either ask for an edge id or for the existence of an edge between a source & a target."))},b.hasUndirectedEdge=function(u,c){if(this.type==="directed")return!1;if(arguments.length===1){var p=""+u,y=this._edges.get(p);return!!y&&y.undirected}if(arguments.length===2){u=""+u,c=""+c;var M=this._nodes.get(u);return!!M&&M.undirected.hasOwnProperty(c)}throw new te("Graph.hasDirectedEdge: invalid arity (".concat(arguments.length,", instead of 1 or 2). You can either ask for an edge id or for the existence of an edge between a source & a target."))},b.hasEdge=function(u,c){if(arguments.length===1){var p=""+u;return this._edges.has(p)}if(arguments.length===2){u=""+u,c=""+c;var y=this._nodes.get(u);return!!y&&(y.out!==void 0&&y.out.hasOwnProperty(c)||y.undirected!==void 0&&y.undirected.hasOwnProperty(c))}throw new te("Graph.hasEdge: invalid arity (".concat(arguments.length,", instead of 1 or 2). You can either ask for an edge id or for the existence of an edge between a source & a target."))},b.directedEdge=function(u,c){if(this.type!=="undirected"){if(u=""+u,c=""+c,this.multi)throw new he("Graph.directedEdge: this method is irrelevant with multigraphs since there might be multiple edges between source & target. See #.directedEdges instead.");var p=this._nodes.get(u);if(!p)throw new W('Graph.directedEdge: could not find the "'.concat(u,'" source node in the graph.'));if(!this._nodes.has(c))throw new W('Graph.directedEdge: could not find the "'.concat(c,'" target node in the graph.'));var y=p.out&&p.out[c]||void 0;return y?y.key:void 0}},b.undirectedEdge=function(u,c){if(this.type!=="directed"){if(u=""+u,c=""+c,this.multi)throw new he("Graph.undirectedEdge: this method is irrelevant with multigraphs since there might be multiple edges between source & target. See #.undirectedEdges instead.");var p=this._nodes.get(u);if(!p)throw new W('Graph.undirectedEdge: could not find the "'.concat(u,'" source node in the graph.'));if(!this._nodes.has(c))throw new W('Graph.undirectedEdge: could not find the "'.concat(c,'" target node in the graph.'));var y=p.undirected&&p.undirected[c]||void 0;return y?y.key:void 0}},b.edge=function(u,c){if(this.multi)throw new he("Graph.edge: this method is irrelevant with multigraphs since there might be multiple edges between source & target. See #.edges instead.");u=""+u,c=""+c;var p=this._nodes.get(u);if(!p)throw new W('Graph.edge: could not find the "'.concat(u,'" source node in the graph.'));if(!this._nodes.has(c))throw new W('Graph.edge: could not find the "'.concat(c,'" target node in the graph.'));var y=p.out&&p.out[c]||p.undirected&&p.undirected[c]||void 0;if(y)return y.key},b.areDirectedNeighbors=function(u,c){u=""+u,c=""+c;var p=this._nodes.get(u);if(!p)throw new W('Graph.areDirectedNeighbors: could not find the "'.concat(u,'" node in the graph.'));return this.type!=="undirected"&&(c in p.in||c in p.out)},b.areOutNeighbors=function(u,c){u=""+u,c=""+c;var p=this._nodes.get(u);if(!p)throw new W('Graph.areOutNeighbors: could not find the "'.concat(u,'" node in the graph.'));return this.type!=="undirected"&&c in p.out},b.areInNeighbors=function(u,c){u=""+u,c=""+c;var p=this._nodes.get(u);if(!p)throw new W('Graph.areInNeighbors: could not find the "'.concat(u,'" node in the graph.'));return this.type!=="undirected"&&c in p.in},b.areUndirectedNeighbors=function(u,c){u=""+u,c=""+c;var p=this._nodes.get(u);if(!p)throw new W('Graph.areUndirectedNeighbors: could not find the "'.concat(u,'" node in the graph.'));return this.type!=="directed"&&c in p.undirected},b.areNeighbors=function(u,c){u=""+u,c=""+c;var p=this._nodes.get(u);if(!p)throw new W('Graph.areNeighbors: could not find the "'.concat(u,'" node in the graph.'));return this.type!=="undirected"&&(c in p.in||c in p.out)||this.type!=="directed"&&c in p.undirected},b.areInboundNeighbors=function(u,c){u=""+u,c=""+c;var p=this._nodes.get(u);if(!p)throw new W('Graph.areInboundNeighbors: could not find the "'.concat(u,'" node in the graph.'));return this.type!=="undirected"&&c in p.in||this.type!=="directed"&&c in p.undirected},b.areOutboundNeighbors=function(u,c){u=""+u,c=""+c;var p=this._nodes.get(u);if(!p)throw new W('Graph.areOutboundNeighbors: could not find the "'.concat(u,'" node in the graph.'));return this.type!=="undirected"&&c in p.out||this.type!=="directed"&&c in p.undirected},b.inDegree=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.inDegree: could not find the "'.concat(u,'" node in the graph.'));return this.type==="undirected"?0:c.inDegree},b.outDegree=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.outDegree: could not find the "'.concat(u,'" node in the graph.'));return this.type==="undirected"?0:c.outDegree},b.directedDegree=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.directedDegree: could not find the "'.concat(u,'" node in the graph.'));return this.type==="undirected"?0:c.inDegree+c.outDegree},b.undirectedDegree=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.undirectedDegree: could not find the "'.concat(u,'" node in the graph.'));return this.type==="directed"?0:c.undirectedDegree},b.inboundDegree=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.inboundDegree: could not find the "'.concat(u,'" node in the graph.'));var p=0;return this.type!=="directed"&&(p+=c.undirectedDegree),this.type!=="undirected"&&(p+=c.inDegree),p},b.outboundDegree=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.outboundDegree: could not find the "'.concat(u,'" node in the graph.'));var p=0;return this.type!=="directed"&&(p+=c.undirectedDegree),this.type!=="undirected"&&(p+=c.outDegree),p},b.degree=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.degree: could not find the "'.concat(u,'" node in the graph.'));var p=0;return this.type!=="directed"&&(p+=c.undirectedDegree),this.type!=="undirected"&&(p+=c.inDegree+c.outDegree),p},b.inDegreeWithoutSelfLoops=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.inDegreeWithoutSelfLoops: could not find the "'.concat(u,'" node in the graph.'));return this.type==="undirected"?0:c.inDegree-c.directedLoops},b.outDegreeWithoutSelfLoops=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.outDegreeWithoutSelfLoops: could not find the "'.concat(u,'" node in the graph.'));return this.type==="undirected"?0:c.outDegree-c.directedLoops},b.directedDegreeWithoutSelfLoops=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.directedDegreeWithoutSelfLoops: could not find the "'.concat(u,'" node in the graph.'));return this.type==="undirected"?0:c.inDegree+c.outDegree-2*c.directedLoops},b.undirectedDegreeWithoutSelfLoops=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.undirectedDegreeWithoutSelfLoops: could not find the "'.concat(u,'" node in the graph.'));return this.type==="directed"?0:c.undirectedDegree-2*c.undirectedLoops},b.inboundDegreeWithoutSelfLoops=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.inboundDegreeWithoutSelfLoops: could not find the "'.concat(u,'" node in the graph.'));var p=0,y=0;return this.type!=="directed"&&(p+=c.undirectedDegree,y+=2*c.undirectedLoops),this.type!=="undirected"&&(p+=c.inDegree,y+=c.directedLoops),p-y},b.outboundDegreeWithoutSelfLoops=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.outboundDegreeWithoutSelfLoops: could not find the "'.concat(u,'" node in the graph.'));var p=0,y=0;return this.type!=="directed"&&(p+=c.undirectedDegree,y+=2*c.undirectedLoops),this.type!=="undirected"&&(p+=c.outDegree,y+=c.directedLoops),p-y},b.degreeWithoutSelfLoops=function(u){u=""+u;var c=this._nodes.get(u);if(!c)throw new W('Graph.degreeWithoutSelfLoops: could not find the "'.concat(u,'" node in the graph.'));var p=0,y=0;return this.type!=="directed"&&(p+=c.undirectedDegree,y+=2*c.undirectedLoops),this.type!=="undirected"&&(p+=c.inDegree+c.outDegree,y+=2*c.directedLoops),p-y},b.source=function(u){u=""+u;var c=this._edges.get(u);if(!c)throw new W('Graph.source: could not find the "'.concat(u,'" edge in the graph.'));return c.source.key},b.target=function(u){u=""+u;var c=this._edges.get(u);if(!c)throw new W('Graph.target: could not find the "'.concat(u,'" edge in the graph.'));return c.target.key},b.extremities=function(u){u=""+u;var c=this._edges.get(u);if(!c)throw new W('Graph.extremities: could not find the "'.concat(u,'" edge in the graph.'));return[c.source.key,c.target.key]},b.opposite=function(u,c){u=""+u,c=""+c;var p=this._edges.get(c);if(!p)throw new W('Graph.opposite: could not find the "'.concat(c,'" edge in the graph.'));var y=p.source.key,M=p.target.key;if(u===y)return M;if(u===M)return y;throw new W('Graph.opposite: the "'.concat(u,'" node is not attached to the "').concat(c,'" edge (').concat(y,", ").concat(M,")."))},b.hasExtremity=function(u,c){u=""+u,c=""+c;var p=this._edges.get(u);if(!p)throw new W('Graph.hasExtremity: could not find the "'.concat(u,'" edge in the graph.'));return p.source.key===c||p.target.key===c},b.isUndirected=function(u){u=""+u;var c=this._edges.get(u);if(!c)throw new W('Graph.isUndirected: could not find the "'.concat(u,'" edge in the graph.'));return c.undirected},b.isDirected=function(u){u=""+u;var c=this._edges.get(u);if(!c)throw new W('Graph.isDirected: could not find the "'.concat(u,'" edge in the graph.'));return!c.undirected},b.isSelfLoop=function(u){u=""+u;var c=this._edges.get(u);if(!c)throw new W('Graph.isSelfLoop: could not find the "'.concat(u,'" edge in the graph.'));return c.source===c.target},b.addNode=function(u,c){var p=function(y,M,A){if(A&&!d(A))throw new te('Graph.addNode: invalid attributes. Expecting an object but got "'.concat(A,'"'));if(M=""+M,A=A||{},y._nodes.has(M))throw new he('Graph.addNode: the "'.concat(M,'" node already exist in the graph.'));var O=new y.NodeDataClass(M,A);return y._nodes.set(M,O),y.emit("nodeAdded",{key:M,attributes:A}),O}(this,u,c);return p.key},b.mergeNode=function(u,c){if(c&&!d(c))throw new te('Graph.mergeNode: invalid attributes. Expecting an object but got "'.concat(c,'"'));u=""+u,c=c||{};var p=this._nodes.get(u);return p?(c&&(l(p.attributes,c),this.emit("nodeAttributesUpdated",{type:"merge",key:u,attributes:p.attributes,data:c})),[u,!1]):(p=new this.NodeDataClass(u,c),this._nodes.set(u,p),this.emit("nodeAdded",{key:u,attributes:c}),[u,!0])},b.updateNode=function(u,c){if(c&&typeof c!="function")throw new te('Graph.updateNode: invalid updater function. Expecting a function but got "'.concat(c,'"'));u=""+u;var p=this._nodes.get(u);if(p){if(c){var y=p.attributes;p.attributes=c(y),this.emit("nodeAttributesUpdated",{type:"replace",key:u,attributes:p.attributes})}return[u,!1]}var M=c?c({}):{};return p=new this.NodeDataClass(u,M),this._nodes.set(u,p),this.emit("nodeAdded",{key:u,attributes:M}),[u,!0]},b.dropNode=function(u){u=""+u;var c,p=this._nodes.get(u);if(!p)throw new W('Graph.dropNode: could not find the "'.concat(u,'" node in the graph.'));if(this.type!=="undirected"){for(var y in p.out){c=p.out[y];do Ft(this,c),c=c.next;while(c)}for(var M in p.in){c=p.in[M];do Ft(this,c),c=c.next;while(c)}}if(this.type!=="directed")for(var A in p.undirected){c=p.undirected[A];do Ft(this,c),c=c.next;while(c)}this._nodes.delete(u),this.emit("nodeDropped",{key:u,attributes:p.attributes})},b.dropEdge=function(u){var c;if(arguments.length>1){var p=""+arguments[0],y=""+arguments[1];if(!(c=h(this,p,y,this.type)))throw new W('Graph.dropEdge: could not find the "'.concat(p,'" -> "').concat(y,'" edge in the graph.'))}else if(u=""+u,!(c=this._edges.get(u)))throw new W('Graph.dropEdge: could not find the "'.concat(u,'" edge in the graph.'));return Ft(this,c),this},b.dropDirectedEdge=function(u,c){if(arguments.length<2)throw new he("Graph.dropDirectedEdge: it does not make sense to try and drop a directed edge by key. What if the edge with this key is undirected? Use #.dropEdge for this purpose instead.");if(this.multi)throw new he("Graph.dropDirectedEdge: cannot use a {source,target} combo when dropping an edge in a MultiGraph since we cannot infer the one you want to delete as there could be multiple ones.");var p=h(this,u=""+u,c=""+c,"directed");if(!p)throw new W('Graph.dropDirectedEdge: could not find a "'.concat(u,'" -> "').concat(c,'" edge in the graph.'));return Ft(this,p),this},b.dropUndirectedEdge=function(u,c){if(arguments.length<2)throw new he("Graph.dropUndirectedEdge: it does not make sense to drop a directed edge by key. What if the edge with this key is undirected? Use #.dropEdge for this purpose instead.");if(this.multi)throw new he("Graph.dropUndirectedEdge: cannot use a {source,target} combo when dropping an edge in a MultiGraph since we cannot infer the one you want to delete as there could be multiple ones.");var p=h(this,u,c,"undirected");if(!p)throw new W('Graph.dropUndirectedEdge: could not find a "'.concat(u,'" -> "').concat(c,'" edge in the graph.'));return Ft(this,p),this},b.clear=function(){this._edges.clear(),this._nodes.clear(),this._resetInstanceCounters(),this.emit("cleared")},b.clearEdges=function(){for(var u,c=this._nodes.values();(u=c.next()).done!==!0;)u.value.clear();this._edges.clear(),this._resetInstanceCounters(),this.emit("edgesCleared")},b.getAttribute=function(u){return this._attributes[u]},b.getAttributes=function(){return this._attributes},b.hasAttribute=function(u){return this._attributes.hasOwnProperty(u)},b.setAttribute=function(u,c){return this._attributes[u]=c,this.emit("attributesUpdated",{type:"set",attributes:this._attributes,name:u}),this},b.updateAttribute=function(u,c){if(typeof c!="function")throw new te("Graph.updateAttribute: updater should be a function.");var p=this._attributes[u];return this._attributes[u]=c(p),this.emit("attributesUpdated",{type:"set",attributes:this._attributes,name:u}),this},b.removeAttribute=function(u){return delete this._attributes[u],this.emit("attributesUpdated",{type:"remove",attributes:this._attributes,name:u}),this},b.replaceAttributes=function(u){if(!d(u))throw new te("Graph.replaceAttributes: provided attributes are not a plain object.");return this._attributes=u,this.emit("attributesUpdated",{type:"replace",attributes:this._attributes}),this},b.mergeAttributes=function(u){if(!d(u))throw new te("Graph.mergeAttributes: provided attributes are not a plain object.");return l(this._attributes,u),this.emit("attributesUpdated",{type:"merge",attributes:this._attributes,data:u}),this},b.updateAttributes=function(u){if(typeof u!="function")throw new te("Graph.updateAttributes: provided updater is not a function.");return this._attributes=u(this._attributes),this.emit("attributesUpdated",{type:"update",attributes:this._attributes}),this},b.updateEachNodeAttributes=function(u,c){if(typeof u!="function")throw new te("Graph.updateEachNodeAttributes: expecting an updater function.");if(c&&!S(c))throw new te("Graph.updateEachNodeAttributes: invalid hints. Expecting an object having the following shape: {attributes?: [string]}");for(var p,y,M=this._nodes.values();(p=M.next()).done!==!0;)(y=p.value).attributes=u(y.key,y.attributes);this.emit("eachNodeAttributesUpdated",{hints:c||null})},b.updateEachEdgeAttributes=function(u,c){if(typeof u!="function")throw new te("Graph.updateEachEdgeAttributes: expecting an updater function.");if(c&&!S(c))throw new te("Graph.updateEachEdgeAttributes: invalid hints. Expecting an object having the following shape: {attributes?: [string]}");for(var p,y,M,A,O=this._edges.values();(p=O.next()).done!==!0;)M=(y=p.value).source,A=y.target,y.attributes=u(y.key,y.attributes,M.key,A.key,M.attributes,A.attributes,y.undirected);this.emit("eachEdgeAttributesUpdated",{hints:c||null})},b.forEachAdjacencyEntry=function(u){if(typeof u!="function")throw new te("Graph.forEachAdjacencyEntry: expecting a callback.");ae(!1,!1,!1,this,u)},b.forEachAdjacencyEntryWithOrphans=function(u){if(typeof u!="function")throw new te("Graph.forEachAdjacencyEntryWithOrphans: expecting a callback.");ae(!1,!1,!0,this,u)},b.forEachAssymetricAdjacencyEntry=function(u){if(typeof u!="function")throw new te("Graph.forEachAssymetricAdjacencyEntry: expecting a callback.");ae(!1,!0,!1,this,u)},b.forEachAssymetricAdjacencyEntryWithOrphans=function(u){if(typeof u!="function")throw new te("Graph.forEachAssymetricAdjacencyEntryWithOrphans: expecting a callback.");ae(!1,!0,!0,this,u)},b.nodes=function(){return typeof Array.from=="function"?Array.from(this._nodes.keys()):re(this._nodes.keys(),this._nodes.size)},b.forEachNode=function(u){if(typeof u!="function")throw new te("Graph.forEachNode: expecting a callback.");for(var c,p,y=this._nodes.values();(c=y.next()).done!==!0;)u((p=c.value).key,p.attributes)},b.findNode=function(u){if(typeof u!="function")throw new te("Graph.findNode: expecting a callback.");for(var c,p,y=this._nodes.values();(c=y.next()).done!==!0;)if(u((p=c.value).key,p.attributes))return p.key},b.mapNodes=function(u){if(typeof u!="function")throw new te("Graph.mapNode: expecting a callback.");for(var c,p,y=this._nodes.values(),M=new Array(this.order),A=0;(c=y.next()).done!==!0;)p=c.value,M[A++]=u(p.key,p.attributes);return M},b.someNode=function(u){if(typeof u!="function")throw new te("Graph.someNode: expecting a callback.");for(var c,p,y=this._nodes.values();(c=y.next()).done!==!0;)if(u((p=c.value).key,p.attributes))return!0;return!1},b.everyNode=function(u){if(typeof u!="function")throw new te("Graph.everyNode: expecting a callback.");for(var c,p,y=this._nodes.values();(c=y.next()).done!==!0;)if(!u((p=c.value).key,p.attributes))return!1;return!0},b.filterNodes=function(u){if(typeof u!="function")throw new te("Graph.filterNodes: expecting a callback.");for(var c,p,y=this._nodes.values(),M=[];(c=y.next()).done!==!0;)u((p=c.value).key,p.attributes)&&M.push(p.key);return M},b.reduceNodes=function(u,c){if(typeof u!="function")throw new te("Graph.reduceNodes: expecting a callback.");if(arguments.length<2)throw new te("Graph.reduceNodes: missing initial value. You must provide it because the callback takes more than one argument and we cannot infer the initial value from the first iteration, as you could with a simple array.");for(var p,y,M=c,A=this._nodes.values();(p=A.next()).done!==!0;)M=u(M,(y=p.value).key,y.attributes);return M},b.nodeEntries=function(){var u=this._nodes.values();return new $(function(){var c=u.next();if(c.done)return c;var p=c.value;return{value:{node:p.key,attributes:p.attributes},done:!1}})},b.export=function(){var u=this,c=new Array(this._nodes.size),p=0;this._nodes.forEach(function(M,A){c[p++]=function(O,B){var z={key:O};return m(B.attributes)||(z.attributes=l({},B.attributes)),z}(A,M)});var y=new Array(this._edges.size);return p=0,this._edges.forEach(function(M,A){y[p++]=function(O,B,z){var K={key:B,source:z.source.key,target:z.target.key};return m(z.attributes)||(K.attributes=l({},z.attributes)),O==="mixed"&&z.undirected&&(K.undirected=!0),K}(u.type,A,M)}),{options:{type:this.type,multi:this.multi,allowSelfLoops:this.allowSelfLoops},attributes:this.getAttributes(),nodes:c,edges:y}},b.import=function(u){var c,p,y,M,A,O=this,B=arguments.length>1&&arguments[1]!==void 0&&arguments[1];if(u instanceof w)return u.forEachNode(function(we,mt){B?O.mergeNode(we,mt):O.addNode(we,mt)}),u.forEachEdge(function(we,mt,Qe,Tt,Qn,Ot,Fn){B?Fn?O.mergeUndirectedEdgeWithKey(we,Qe,Tt,mt):O.mergeDirectedEdgeWithKey(we,Qe,Tt,mt):Fn?O.addUndirectedEdgeWithKey(we,Qe,Tt,mt):O.addDirectedEdgeWithKey(we,Qe,Tt,mt)}),this;if(!d(u))throw new te("Graph.import: invalid argument. Expecting a serialized graph or, alternatively, a Graph instance.");if(u.attributes){if(!d(u.attributes))throw new te("Graph.import: invalid attributes. Expecting a plain object.");B?this.mergeAttributes(u.attributes):this.replaceAttributes(u.attributes)}if(u.nodes){if(y=u.nodes,!Array.isArray(y))throw new te("Graph.import: invalid nodes. Expecting an array.");for(c=0,p=y.length;c<p;c++){Me(M=y[c]);var z=M,K=z.key,ne=z.attributes;B?this.mergeNode(K,ne):this.addNode(K,ne)}}if(u.edges){var fe=!1;if(this.type==="undirected"&&(fe=!0),y=u.edges,!Array.isArray(y))throw new te("Graph.import: invalid edges. Expecting an array.");for(c=0,p=y.length;c<p;c++){Se(A=y[c]);var pe=A,Ie=pe.source,ze=pe.target,Ge=pe.attributes,at=pe.undirected,Ve=at===void 0?fe:at;"key"in A?(B?Ve?this.mergeUndirectedEdgeWithKey:this.mergeDirectedEdgeWithKey:Ve?this.addUndirectedEdgeWithKey:this.addDirectedEdgeWithKey).call(this,A.key,Ie,ze,Ge):(B?Ve?this.mergeUndirectedEdge:this.mergeDirectedEdge:Ve?this.addUndirectedEdge:this.addDirectedEdge).call(this,Ie,ze,Ge)}}return this},b.nullCopy=function(u){var c=new w(l({},this._options,u));return c.replaceAttributes(l({},this.getAttributes())),c},b.emptyCopy=function(u){var c=this.nullCopy(u);return this._nodes.forEach(function(p,y){var M=l({},p.attributes);p=new c.NodeDataClass(y,M),c._nodes.set(y,p)}),c},b.copy=function(u){if(typeof(u=u||{}).type=="string"&&u.type!==this.type&&u.type!=="mixed")throw new he('Graph.copy: cannot create an incompatible copy from "'.concat(this.type,'" type to "').concat(u.type,'" because this would mean losing information about the current graph.'));if(typeof u.multi=="boolean"&&u.multi!==this.multi&&u.multi!==!0)throw new he("Graph.copy: cannot create an incompatible copy by downgrading a multi graph to a simple one because this would mean losing information about the current graph.");if(typeof u.allowSelfLoops=="boolean"&&u.allowSelfLoops!==this.allowSelfLoops&&u.allowSelfLoops!==!0)throw new he("Graph.copy: cannot create an incompatible copy from a graph allowing self loops to one that does not because this would mean losing information about the current graph.");for(var c,p,y=this.emptyCopy(u),M=this._edges.values();(c=M.next()).done!==!0;)or(y,"copy",!1,(p=c.value).undirected,p.key,p.source.key,p.target.key,l({},p.attributes));return y},b.toJSON=function(){return this.export()},b.toString=function(){return"[object Graph]"},b.inspect=function(){var u=this,c={};this._nodes.forEach(function(O,B){c[B]=O.attributes});var p={},y={};this._edges.forEach(function(O,B){var z,K=O.undirected?"--":"->",ne="",fe=O.source.key,pe=O.target.key;O.undirected&&fe>pe&&(z=fe,fe=pe,pe=z);var Ie="(".concat(fe,")").concat(K,"(").concat(pe,")");B.startsWith("geid_")?u.multi&&(y[Ie]===void 0?y[Ie]=0:y[Ie]++,ne+="".concat(y[Ie],". ")):ne+="[".concat(B,"]: "),p[ne+=Ie]=O.attributes});var M={};for(var A in this)this.hasOwnProperty(A)&&!nt.has(A)&&typeof this[A]!="function"&&i(A)!=="symbol"&&(M[A]=this[A]);return M.attributes=this._attributes,M.nodes=c,M.edges=p,f(M,"constructor",this.constructor),M},w}(_.exports.EventEmitter);typeof Symbol<"u"&&(st.prototype[Symbol.for("nodejs.util.inspect.custom")]=st.prototype.inspect),[{name:function(x){return"".concat(x,"Edge")},generateKey:!0},{name:function(x){return"".concat(x,"DirectedEdge")},generateKey:!0,type:"directed"},{name:function(x){return"".concat(x,"UndirectedEdge")},generateKey:!0,type:"undirected"},{name:function(x){return"".concat(x,"EdgeWithKey")}},{name:function(x){return"".concat(x,"DirectedEdgeWithKey")},type:"directed"},{name:function(x){return"".concat(x,"UndirectedEdgeWithKey")},type:"undirected"}].forEach(function(x){["add","merge","update"].forEach(function(w){var b=x.name(w),u=w==="add"?or:Nr;x.generateKey?st.prototype[b]=function(c,p,y){return u(this,b,!0,(x.type||this.type)==="undirected",null,c,p,y,w==="update")}:st.prototype[b]=function(c,p,y,M){return u(this,b,!1,(x.type||this.type)==="undirected",c,p,y,M,w==="update")}})}),function(x){G.forEach(function(w){var b=w.name,u=w.attacher;u(x,b("Node"),0),u(x,b("Source"),1),u(x,b("Target"),2),u(x,b("Opposite"),3)})}(st),function(x){Ut.forEach(function(w){var b=w.name,u=w.attacher;u(x,b("Edge"),"mixed"),u(x,b("DirectedEdge"),"directed"),u(x,b("UndirectedEdge"),"undirected")})}(st),function(x){ht.forEach(function(w){(function(b,u){var c=u.name,p=u.type,y=u.direction;b.prototype[c]=function(M,A){if(p!=="mixed"&&this.type!=="mixed"&&p!==this.type)return[];if(!arguments.length)return se(this,p);if(arguments.length===1){M=""+M;var O=this._nodes.get(M);if(O===void 0)throw new W("Graph.".concat(c,': could not find the "').concat(M,'" node in the graph.'));return Je(this.multi,p==="mixed"?this.type:p,y,O)}if(arguments.length===2){M=""+M,A=""+A;var B=this._nodes.get(M);if(!B)throw new W("Graph.".concat(c,':  could not find the "').concat(M,'" source node in the graph.'));if(!this._nodes.has(A))throw new W("Graph.".concat(c,':  could not find the "').concat(A,'" target node in the graph.'));return Ne(p,this.multi,y,B,A)}throw new te("Graph.".concat(c,": too many arguments (expecting 0, 1 or 2 and got ").concat(arguments.length,")."))}})(x,w),function(b,u){var c=u.name,p=u.type,y=u.direction,M="forEach"+c[0].toUpperCase()+c.slice(1,-1);b.prototype[M]=function(z,K,ne){if(p==="mixed"||this.type==="mixed"||p===this.type){if(arguments.length===1)return Le(!1,this,p,ne=z);if(arguments.length===2){z=""+z,ne=K;var fe=this._nodes.get(z);if(fe===void 0)throw new W("Graph.".concat(M,': could not find the "').concat(z,'" node in the graph.'));return Ee(!1,this.multi,p==="mixed"?this.type:p,y,fe,ne)}if(arguments.length===3){z=""+z,K=""+K;var pe=this._nodes.get(z);if(!pe)throw new W("Graph.".concat(M,':  could not find the "').concat(z,'" source node in the graph.'));if(!this._nodes.has(K))throw new W("Graph.".concat(M,':  could not find the "').concat(K,'" target node in the graph.'));return Te(!1,p,this.multi,y,pe,K,ne)}throw new te("Graph.".concat(M,": too many arguments (expecting 1, 2 or 3 and got ").concat(arguments.length,")."))}};var A="map"+c[0].toUpperCase()+c.slice(1);b.prototype[A]=function(){var z,K=Array.prototype.slice.call(arguments),ne=K.pop();if(K.length===0){var fe=0;p!=="directed"&&(fe+=this.undirectedSize),p!=="undirected"&&(fe+=this.directedSize),z=new Array(fe);var pe=0;K.push(function(Ie,ze,Ge,at,Ve,we,mt){z[pe++]=ne(Ie,ze,Ge,at,Ve,we,mt)})}else z=[],K.push(function(Ie,ze,Ge,at,Ve,we,mt){z.push(ne(Ie,ze,Ge,at,Ve,we,mt))});return this[M].apply(this,K),z};var O="filter"+c[0].toUpperCase()+c.slice(1);b.prototype[O]=function(){var z=Array.prototype.slice.call(arguments),K=z.pop(),ne=[];return z.push(function(fe,pe,Ie,ze,Ge,at,Ve){K(fe,pe,Ie,ze,Ge,at,Ve)&&ne.push(fe)}),this[M].apply(this,z),ne};var B="reduce"+c[0].toUpperCase()+c.slice(1);b.prototype[B]=function(){var z,K,ne=Array.prototype.slice.call(arguments);if(ne.length<2||ne.length>4)throw new te("Graph.".concat(B,": invalid number of arguments (expecting 2, 3 or 4 and got ").concat(ne.length,")."));if(typeof ne[ne.length-1]=="function"&&typeof ne[ne.length-2]!="function")throw new te("Graph.".concat(B,": missing initial value. You must provide it because the callback takes more than one argument and we cannot infer the initial value from the first iteration, as you could with a simple array."));ne.length===2?(z=ne[0],K=ne[1],ne=[]):ne.length===3?(z=ne[1],K=ne[2],ne=[ne[0]]):ne.length===4&&(z=ne[2],K=ne[3],ne=[ne[0],ne[1]]);var fe=K;return ne.push(function(pe,Ie,ze,Ge,at,Ve,we){fe=z(fe,pe,Ie,ze,Ge,at,Ve,we)}),this[M].apply(this,ne),fe}}(x,w),function(b,u){var c=u.name,p=u.type,y=u.direction,M="find"+c[0].toUpperCase()+c.slice(1,-1);b.prototype[M]=function(B,z,K){if(p!=="mixed"&&this.type!=="mixed"&&p!==this.type)return!1;if(arguments.length===1)return Le(!0,this,p,K=B);if(arguments.length===2){B=""+B,K=z;var ne=this._nodes.get(B);if(ne===void 0)throw new W("Graph.".concat(M,': could not find the "').concat(B,'" node in the graph.'));return Ee(!0,this.multi,p==="mixed"?this.type:p,y,ne,K)}if(arguments.length===3){B=""+B,z=""+z;var fe=this._nodes.get(B);if(!fe)throw new W("Graph.".concat(M,':  could not find the "').concat(B,'" source node in the graph.'));if(!this._nodes.has(z))throw new W("Graph.".concat(M,':  could not find the "').concat(z,'" target node in the graph.'));return Te(!0,p,this.multi,y,fe,z,K)}throw new te("Graph.".concat(M,": too many arguments (expecting 1, 2 or 3 and got ").concat(arguments.length,")."))};var A="some"+c[0].toUpperCase()+c.slice(1,-1);b.prototype[A]=function(){var B=Array.prototype.slice.call(arguments),z=B.pop();return B.push(function(K,ne,fe,pe,Ie,ze,Ge){return z(K,ne,fe,pe,Ie,ze,Ge)}),!!this[M].apply(this,B)};var O="every"+c[0].toUpperCase()+c.slice(1,-1);b.prototype[O]=function(){var B=Array.prototype.slice.call(arguments),z=B.pop();return B.push(function(K,ne,fe,pe,Ie,ze,Ge){return!z(K,ne,fe,pe,Ie,ze,Ge)}),!this[M].apply(this,B)}}(x,w),function(b,u){var c=u.name,p=u.type,y=u.direction,M=c.slice(0,-1)+"Entries";b.prototype[M]=function(A,O){if(p!=="mixed"&&this.type!=="mixed"&&p!==this.type)return $.empty();if(!arguments.length)return be(this,p);if(arguments.length===1){A=""+A;var B=this._nodes.get(A);if(!B)throw new W("Graph.".concat(M,': could not find the "').concat(A,'" node in the graph.'));return me(p,y,B)}if(arguments.length===2){A=""+A,O=""+O;var z=this._nodes.get(A);if(!z)throw new W("Graph.".concat(M,':  could not find the "').concat(A,'" source node in the graph.'));if(!this._nodes.has(O))throw new W("Graph.".concat(M,':  could not find the "').concat(O,'" target node in the graph.'));return Ue(p,y,z,O)}throw new te("Graph.".concat(M,": too many arguments (expecting 0, 1 or 2 and got ").concat(arguments.length,")."))}}(x,w)})}(st),function(x){Ae.forEach(function(w){xe(x,w),function(b,u){var c=u.name,p=u.type,y=u.direction,M="forEach"+c[0].toUpperCase()+c.slice(1,-1);b.prototype[M]=function(z,K){if(p==="mixed"||this.type==="mixed"||p===this.type){z=""+z;var ne=this._nodes.get(z);if(ne===void 0)throw new W("Graph.".concat(M,': could not find the "').concat(z,'" node in the graph.'));rt(!1,p==="mixed"?this.type:p,y,ne,K)}};var A="map"+c[0].toUpperCase()+c.slice(1);b.prototype[A]=function(z,K){var ne=[];return this[M](z,function(fe,pe){ne.push(K(fe,pe))}),ne};var O="filter"+c[0].toUpperCase()+c.slice(1);b.prototype[O]=function(z,K){var ne=[];return this[M](z,function(fe,pe){K(fe,pe)&&ne.push(fe)}),ne};var B="reduce"+c[0].toUpperCase()+c.slice(1);b.prototype[B]=function(z,K,ne){if(arguments.length<3)throw new te("Graph.".concat(B,": missing initial value. You must provide it because the callback takes more than one argument and we cannot infer the initial value from the first iteration, as you could with a simple array."));var fe=ne;return this[M](z,function(pe,Ie){fe=K(fe,pe,Ie)}),fe}}(x,w),function(b,u){var c=u.name,p=u.type,y=u.direction,M=c[0].toUpperCase()+c.slice(1,-1),A="find"+M;b.prototype[A]=function(z,K){if(p==="mixed"||this.type==="mixed"||p===this.type){z=""+z;var ne=this._nodes.get(z);if(ne===void 0)throw new W("Graph.".concat(A,': could not find the "').concat(z,'" node in the graph.'));return rt(!0,p==="mixed"?this.type:p,y,ne,K)}};var O="some"+M;b.prototype[O]=function(z,K){return!!this[A](z,K)};var B="every"+M;b.prototype[B]=function(z,K){return!this[A](z,function(ne,fe){return!K(ne,fe)})}}(x,w),ee(x,w)})}(st);var cr=function(x){function w(b){var u=l({type:"directed"},b);if("multi"in u&&u.multi!==!1)throw new te("DirectedGraph.from: inconsistent indication that the graph should be multi in given options!");if(u.type!=="directed")throw new te('DirectedGraph.from: inconsistent "'+u.type+'" type in given options!');return x.call(this,u)||this}return e(w,x),w}(st),lr=function(x){function w(b){var u=l({type:"undirected"},b);if("multi"in u&&u.multi!==!1)throw new te("UndirectedGraph.from: inconsistent indication that the graph should be multi in given options!");if(u.type!=="undirected")throw new te('UndirectedGraph.from: inconsistent "'+u.type+'" type in given options!');return x.call(this,u)||this}return e(w,x),w}(st),jn=function(x){function w(b){var u=l({multi:!0},b);if("multi"in u&&u.multi!==!0)throw new te("MultiGraph.from: inconsistent indication that the graph should be simple in given options!");return x.call(this,u)||this}return e(w,x),w}(st),hr=function(x){function w(b){var u=l({type:"directed",multi:!0},b);if("multi"in u&&u.multi!==!0)throw new te("MultiDirectedGraph.from: inconsistent indication that the graph should be simple in given options!");if(u.type!=="directed")throw new te('MultiDirectedGraph.from: inconsistent "'+u.type+'" type in given options!');return x.call(this,u)||this}return e(w,x),w}(st),Jn=function(x){function w(b){var u=l({type:"undirected",multi:!0},b);if("multi"in u&&u.multi!==!0)throw new te("MultiUndirectedGraph.from: inconsistent indication that the graph should be simple in given options!");if(u.type!=="undirected")throw new te('MultiUndirectedGraph.from: inconsistent "'+u.type+'" type in given options!');return x.call(this,u)||this}return e(w,x),w}(st);function gn(x){x.from=function(w,b){var u=l({},w.options,b),c=new x(u);return c.import(w),c}}return gn(st),gn(cr),gn(lr),gn(jn),gn(hr),gn(Jn),st.Graph=st,st.DirectedGraph=cr,st.UndirectedGraph=lr,st.MultiGraph=jn,st.MultiDirectedGraph=hr,st.MultiUndirectedGraph=Jn,st.InvalidArgumentsGraphError=te,st.NotFoundGraphError=W,st.UsageGraphError=he,st})});var pa=js((Oy,fa)=>{"use strict";var Ei=typeof Reflect=="object"?Reflect:null,rl=Ei&&typeof Ei.apply=="function"?Ei.apply:function(e,t,n){return Function.prototype.apply.call(e,t,n)},Or;Ei&&typeof Ei.ownKeys=="function"?Or=Ei.ownKeys:Object.getOwnPropertySymbols?Or=function(e){return Object.getOwnPropertyNames(e).concat(Object.getOwnPropertySymbols(e))}:Or=function(e){return Object.getOwnPropertyNames(e)};function hd(i){console&&console.warn&&console.warn(i)}var al=Number.isNaN||function(e){return e!==e};function ot(){ot.init.call(this)}fa.exports=ot;fa.exports.once=pd;ot.EventEmitter=ot;ot.prototype._events=void 0;ot.prototype._eventsCount=0;ot.prototype._maxListeners=void 0;var sl=10;function kr(i){if(typeof i!="function")throw new TypeError('The "listener" argument must be of type Function. Received type '+typeof i)}Object.defineProperty(ot,"defaultMaxListeners",{enumerable:!0,get:function(){return sl},set:function(i){if(typeof i!="number"||i<0||al(i))throw new RangeError('The value of "defaultMaxListeners" is out of range. It must be a non-negative number. Received '+i+".");sl=i}});ot.init=function(){(this._events===void 0||this._events===Object.getPrototypeOf(this)._events)&&(this._events=Object.create(null),this._eventsCount=0),this._maxListeners=this._maxListeners||void 0};ot.prototype.setMaxListeners=function(e){if(typeof e!="number"||e<0||al(e))throw new RangeError('The value of "n" is out of range. It must be a non-negative number. Received '+e+".");return this._maxListeners=e,this};function ol(i){return i._maxListeners===void 0?ot.defaultMaxListeners:i._maxListeners}ot.prototype.getMaxListeners=function(){return ol(this)};ot.prototype.emit=function(e){for(var t=[],n=1;n<arguments.length;n++)t.push(arguments[n]);var r=e==="error",s=this._events;if(s!==void 0)r=r&&s.error===void 0;else if(!r)return!1;if(r){var a;if(t.length>0&&(a=t[0]),a instanceof Error)throw a;var o=new Error("Unhandled error."+(a?" ("+a.message+")":""));throw o.context=a,o}var l=s[e];if(l===void 0)return!1;if(typeof l=="function")rl(l,this,t);else for(var h=l.length,d=dl(l,h),n=0;n<h;++n)rl(d[n],this,t);return!0};function cl(i,e,t,n){var r,s,a;if(kr(t),s=i._events,s===void 0?(s=i._events=Object.create(null),i._eventsCount=0):(s.newListener!==void 0&&(i.emit("newListener",e,t.listener?t.listener:t),s=i._events),a=s[e]),a===void 0)a=s[e]=t,++i._eventsCount;else if(typeof a=="function"?a=s[e]=n?[t,a]:[a,t]:n?a.unshift(t):a.push(t),r=ol(i),r>0&&a.length>r&&!a.warned){a.warned=!0;var o=new Error("Possible EventEmitter memory leak detected. "+a.length+" "+String(e)+" listeners added. Use emitter.setMaxListeners() to increase limit");o.name="MaxListenersExceededWarning",o.emitter=i,o.type=e,o.count=a.length,hd(o)}return i}ot.prototype.addListener=function(e,t){return cl(this,e,t,!1)};ot.prototype.on=ot.prototype.addListener;ot.prototype.prependListener=function(e,t){return cl(this,e,t,!0)};function ud(){if(!this.fired)return this.target.removeListener(this.type,this.wrapFn),this.fired=!0,arguments.length===0?this.listener.call(this.target):this.listener.apply(this.target,arguments)}function ll(i,e,t){var n={fired:!1,wrapFn:void 0,target:i,type:e,listener:t},r=ud.bind(n);return r.listener=t,n.wrapFn=r,r}ot.prototype.once=function(e,t){return kr(t),this.on(e,ll(this,e,t)),this};ot.prototype.prependOnceListener=function(e,t){return kr(t),this.prependListener(e,ll(this,e,t)),this};ot.prototype.removeListener=function(e,t){var n,r,s,a,o;if(kr(t),r=this._events,r===void 0)return this;if(n=r[e],n===void 0)return this;if(n===t||n.listener===t)--this._eventsCount===0?this._events=Object.create(null):(delete r[e],r.removeListener&&this.emit("removeListener",e,n.listener||t));else if(typeof n!="function"){for(s=-1,a=n.length-1;a>=0;a--)if(n[a]===t||n[a].listener===t){o=n[a].listener,s=a;break}if(s<0)return this;s===0?n.shift():dd(n,s),n.length===1&&(r[e]=n[0]),r.removeListener!==void 0&&this.emit("removeListener",e,o||t)}return this};ot.prototype.off=ot.prototype.removeListener;ot.prototype.removeAllListeners=function(e){var t,n,r;if(n=this._events,n===void 0)return this;if(n.removeListener===void 0)return arguments.length===0?(this._events=Object.create(null),this._eventsCount=0):n[e]!==void 0&&(--this._eventsCount===0?this._events=Object.create(null):delete n[e]),this;if(arguments.length===0){var s=Object.keys(n),a;for(r=0;r<s.length;++r)a=s[r],a!=="removeListener"&&this.removeAllListeners(a);return this.removeAllListeners("removeListener"),this._events=Object.create(null),this._eventsCount=0,this}if(t=n[e],typeof t=="function")this.removeListener(e,t);else if(t!==void 0)for(r=t.length-1;r>=0;r--)this.removeListener(e,t[r]);return this};function hl(i,e,t){var n=i._events;if(n===void 0)return[];var r=n[e];return r===void 0?[]:typeof r=="function"?t?[r.listener||r]:[r]:t?fd(r):dl(r,r.length)}ot.prototype.listeners=function(e){return hl(this,e,!0)};ot.prototype.rawListeners=function(e){return hl(this,e,!1)};ot.listenerCount=function(i,e){return typeof i.listenerCount=="function"?i.listenerCount(e):ul.call(i,e)};ot.prototype.listenerCount=ul;function ul(i){var e=this._events;if(e!==void 0){var t=e[i];if(typeof t=="function")return 1;if(t!==void 0)return t.length}return 0}ot.prototype.eventNames=function(){return this._eventsCount>0?Or(this._events):[]};function dl(i,e){for(var t=new Array(e),n=0;n<e;++n)t[n]=i[n];return t}function dd(i,e){for(;e+1<i.length;e++)i[e]=i[e+1];i.pop()}function fd(i){for(var e=new Array(i.length),t=0;t<e.length;++t)e[t]=i[t].listener||i[t];return e}function pd(i,e){return new Promise(function(t,n){function r(a){i.removeListener(e,s),n(a)}function s(){typeof i.removeListener=="function"&&i.removeListener("error",r),t([].slice.call(arguments))}fl(i,e,s,{once:!0}),e!=="error"&&md(i,r,{once:!0})})}function md(i,e,t){typeof i.on=="function"&&fl(i,"error",e,t)}function fl(i,e,t,n){if(typeof i.on=="function")n.once?i.once(e,t):i.on(e,t);else if(typeof i.addEventListener=="function")i.addEventListener(e,function r(s){n.once&&i.removeEventListener(e,r),t(s)});else throw new TypeError('The "emitter" argument must be of type EventEmitter. Received type '+typeof i)}});var ma=js((zy,ml)=>{ml.exports=function(e){return e!==null&&typeof e=="object"&&typeof e.addUndirectedEdgeWithKey=="function"&&typeof e.dropNode=="function"&&typeof e.multi=="boolean"}});var gu=dr(Lc());function Tu(i,e){if(typeof i!="object"||!i)return i;var t=i[Symbol.toPrimitive];if(t!==void 0){var n=t.call(i,e||"default");if(typeof n!="object")return n;throw new TypeError("@@toPrimitive must return a primitive value.")}return(e==="string"?String:Number)(i)}function ti(i){var e=Tu(i,"string");return typeof e=="symbol"?e:e+""}function yt(i,e){if(!(i instanceof e))throw new TypeError("Cannot call a class as a function")}function Ic(i,e){for(var t=0;t<e.length;t++){var n=e[t];n.enumerable=n.enumerable||!1,n.configurable=!0,"value"in n&&(n.writable=!0),Object.defineProperty(i,ti(n.key),n)}}function xt(i,e,t){return e&&Ic(i.prototype,e),t&&Ic(i,t),Object.defineProperty(i,"prototype",{writable:!1}),i}function ei(i){return ei=Object.setPrototypeOf?Object.getPrototypeOf.bind():function(e){return e.__proto__||Object.getPrototypeOf(e)},ei(i)}function Dc(){try{var i=!Boolean.prototype.valueOf.call(Reflect.construct(Boolean,[],function(){}))}catch{}return(Dc=function(){return!!i})()}function Au(i){if(i===void 0)throw new ReferenceError("this hasn't been initialised - super() hasn't been called");return i}function Cu(i,e){if(e&&(typeof e=="object"||typeof e=="function"))return e;if(e!==void 0)throw new TypeError("Derived constructors may only return object or undefined");return Au(i)}function Pt(i,e,t){return e=ei(e),Cu(i,Dc()?Reflect.construct(e,t||[],ei(i).constructor):e.apply(i,t))}function ea(i,e){return ea=Object.setPrototypeOf?Object.setPrototypeOf.bind():function(t,n){return t.__proto__=n,t},ea(i,e)}function Lt(i,e){if(typeof e!="function"&&e!==null)throw new TypeError("Super expression must either be null or a function");i.prototype=Object.create(e&&e.prototype,{constructor:{value:i,writable:!0,configurable:!0}}),Object.defineProperty(i,"prototype",{writable:!1}),e&&ea(i,e)}function Ru(i){if(Array.isArray(i))return i}function Pu(i,e){var t=i==null?null:typeof Symbol<"u"&&i[Symbol.iterator]||i["@@iterator"];if(t!=null){var n,r,s,a,o=[],l=!0,h=!1;try{if(s=(t=t.call(i)).next,e===0){if(Object(t)!==t)return;l=!1}else for(;!(l=(n=s.call(t)).done)&&(o.push(n.value),o.length!==e);l=!0);}catch(d){h=!0,r=d}finally{try{if(!l&&t.return!=null&&(a=t.return(),Object(a)!==a))return}finally{if(h)throw r}}return o}}function Ur(i,e){(e==null||e>i.length)&&(e=i.length);for(var t=0,n=Array(e);t<e;t++)n[t]=i[t];return n}function ra(i,e){if(i){if(typeof i=="string")return Ur(i,e);var t={}.toString.call(i).slice(8,-1);return t==="Object"&&i.constructor&&(t=i.constructor.name),t==="Map"||t==="Set"?Array.from(i):t==="Arguments"||/^(?:Ui|I)nt(?:8|16|32)(?:Clamped)?Array$/.test(t)?Ur(i,e):void 0}}function Lu(){throw new TypeError(`Invalid attempt to destructure non-iterable instance.
In order to be iterable, non-array objects must have a [Symbol.iterator]() method.`)}function Bn(i,e){return Ru(i)||Pu(i,e)||ra(i,e)||Lu()}var ta={black:"#000000",silver:"#C0C0C0",gray:"#808080",grey:"#808080",white:"#FFFFFF",maroon:"#800000",red:"#FF0000",purple:"#800080",fuchsia:"#FF00FF",green:"#008000",lime:"#00FF00",olive:"#808000",yellow:"#FFFF00",navy:"#000080",blue:"#0000FF",teal:"#008080",aqua:"#00FFFF",darkblue:"#00008B",mediumblue:"#0000CD",darkgreen:"#006400",darkcyan:"#008B8B",deepskyblue:"#00BFFF",darkturquoise:"#00CED1",mediumspringgreen:"#00FA9A",springgreen:"#00FF7F",cyan:"#00FFFF",midnightblue:"#191970",dodgerblue:"#1E90FF",lightseagreen:"#20B2AA",forestgreen:"#228B22",seagreen:"#2E8B57",darkslategray:"#2F4F4F",darkslategrey:"#2F4F4F",limegreen:"#32CD32",mediumseagreen:"#3CB371",turquoise:"#40E0D0",royalblue:"#4169E1",steelblue:"#4682B4",darkslateblue:"#483D8B",mediumturquoise:"#48D1CC",indigo:"#4B0082",darkolivegreen:"#556B2F",cadetblue:"#5F9EA0",cornflowerblue:"#6495ED",rebeccapurple:"#663399",mediumaquamarine:"#66CDAA",dimgray:"#696969",dimgrey:"#696969",slateblue:"#6A5ACD",olivedrab:"#6B8E23",slategray:"#708090",slategrey:"#708090",lightslategray:"#778899",lightslategrey:"#778899",mediumslateblue:"#7B68EE",lawngreen:"#7CFC00",chartreuse:"#7FFF00",aquamarine:"#7FFFD4",skyblue:"#87CEEB",lightskyblue:"#87CEFA",blueviolet:"#8A2BE2",darkred:"#8B0000",darkmagenta:"#8B008B",saddlebrown:"#8B4513",darkseagreen:"#8FBC8F",lightgreen:"#90EE90",mediumpurple:"#9370DB",darkviolet:"#9400D3",palegreen:"#98FB98",darkorchid:"#9932CC",yellowgreen:"#9ACD32",sienna:"#A0522D",brown:"#A52A2A",darkgray:"#A9A9A9",darkgrey:"#A9A9A9",lightblue:"#ADD8E6",greenyellow:"#ADFF2F",paleturquoise:"#AFEEEE",lightsteelblue:"#B0C4DE",powderblue:"#B0E0E6",firebrick:"#B22222",darkgoldenrod:"#B8860B",mediumorchid:"#BA55D3",rosybrown:"#BC8F8F",darkkhaki:"#BDB76B",mediumvioletred:"#C71585",indianred:"#CD5C5C",peru:"#CD853F",chocolate:"#D2691E",tan:"#D2B48C",lightgray:"#D3D3D3",lightgrey:"#D3D3D3",thistle:"#D8BFD8",orchid:"#DA70D6",goldenrod:"#DAA520",palevioletred:"#DB7093",crimson:"#DC143C",gainsboro:"#DCDCDC",plum:"#DDA0DD",burlywood:"#DEB887",lightcyan:"#E0FFFF",lavender:"#E6E6FA",darksalmon:"#E9967A",violet:"#EE82EE",palegoldenrod:"#EEE8AA",lightcoral:"#F08080",khaki:"#F0E68C",aliceblue:"#F0F8FF",honeydew:"#F0FFF0",azure:"#F0FFFF",sandybrown:"#F4A460",wheat:"#F5DEB3",beige:"#F5F5DC",whitesmoke:"#F5F5F5",mintcream:"#F5FFFA",ghostwhite:"#F8F8FF",salmon:"#FA8072",antiquewhite:"#FAEBD7",linen:"#FAF0E6",lightgoldenrodyellow:"#FAFAD2",oldlace:"#FDF5E6",magenta:"#FF00FF",deeppink:"#FF1493",orangered:"#FF4500",tomato:"#FF6347",hotpink:"#FF69B4",coral:"#FF7F50",darkorange:"#FF8C00",lightsalmon:"#FFA07A",orange:"#FFA500",lightpink:"#FFB6C1",pink:"#FFC0CB",gold:"#FFD700",peachpuff:"#FFDAB9",navajowhite:"#FFDEAD",moccasin:"#FFE4B5",bisque:"#FFE4C4",mistyrose:"#FFE4E1",blanchedalmond:"#FFEBCD",papayawhip:"#FFEFD5",lavenderblush:"#FFF0F5",seashell:"#FFF5EE",cornsilk:"#FFF8DC",lemonchiffon:"#FFFACD",floralwhite:"#FFFAF0",snow:"#FFFAFA",lightyellow:"#FFFFE0",ivory:"#FFFFF0"};var Nc=new Int8Array(4),na=new Int32Array(Nc.buffer,0,1),Iu=new Float32Array(Nc.buffer,0,1),Du=/^\s*rgba?\s*\(/,Nu=/^\s*rgba?\s*\(\s*([0-9]*)\s*,\s*([0-9]*)\s*,\s*([0-9]*)(?:\s*,\s*(.*)?)?\)\s*$/;function Uu(i){var e=0,t=0,n=0,r=1;if(i[0]==="#")i.length===4?(e=parseInt(i.charAt(1)+i.charAt(1),16),t=parseInt(i.charAt(2)+i.charAt(2),16),n=parseInt(i.charAt(3)+i.charAt(3),16)):(e=parseInt(i.charAt(1)+i.charAt(2),16),t=parseInt(i.charAt(3)+i.charAt(4),16),n=parseInt(i.charAt(5)+i.charAt(6),16)),i.length===9&&(r=parseInt(i.charAt(7)+i.charAt(8),16)/255);else if(Du.test(i)){var s=i.match(Nu);s&&(e=+s[1],t=+s[2],n=+s[3],s[4]&&(r=+s[4]))}return{r:e,g:t,b:n,a:r}}var Mi={};for(fr in ta)Mi[fr]=wi(ta[fr]),Mi[ta[fr]]=Mi[fr];var fr;function Uc(i,e,t,n,r){return na[0]=n<<24|t<<16|e<<8|i,r&&(na[0]=na[0]&4278190079),Iu[0]}function wi(i){if(i=i.toLowerCase(),typeof Mi[i]<"u")return Mi[i];var e=Uu(i),t=e.r,n=e.g,r=e.b,s=e.a;s=s*255|0;var a=Uc(t,n,r,s,!0);return Mi[i]=a,a}var ia={};function sa(i){if(typeof ia[i]<"u")return ia[i];var e=(i&16711680)>>>16,t=(i&65280)>>>8,n=i&255,r=255,s=Uc(e,t,n,r,!0);return ia[i]=s,s}function aa(i,e,t,n){return t+(e<<8)+(i<<16)}function oa(i,e,t,n,r,s){var a=Math.floor(t/s*r),o=Math.floor(i.drawingBufferHeight/s-n/s*r),l=new Uint8Array(4);i.bindFramebuffer(i.FRAMEBUFFER,e),i.readPixels(a,o,1,1,i.RGBA,i.UNSIGNED_BYTE,l);var h=Bn(l,4),d=h[0],m=h[1],f=h[2],v=h[3];return[d,m,f,v]}function ce(i,e,t){return(e=ti(e))in i?Object.defineProperty(i,e,{value:t,enumerable:!0,configurable:!0,writable:!0}):i[e]=t,i}function Fc(i,e){var t=Object.keys(i);if(Object.getOwnPropertySymbols){var n=Object.getOwnPropertySymbols(i);e&&(n=n.filter(function(r){return Object.getOwnPropertyDescriptor(i,r).enumerable})),t.push.apply(t,n)}return t}function Re(i){for(var e=1;e<arguments.length;e++){var t=arguments[e]!=null?arguments[e]:{};e%2?Fc(Object(t),!0).forEach(function(n){ce(i,n,t[n])}):Object.getOwnPropertyDescriptors?Object.defineProperties(i,Object.getOwnPropertyDescriptors(t)):Fc(Object(t)).forEach(function(n){Object.defineProperty(i,n,Object.getOwnPropertyDescriptor(t,n))})}return i}function Fu(i,e){for(;!{}.hasOwnProperty.call(i,e)&&(i=ei(i))!==null;);return i}function ha(){return ha=typeof Reflect<"u"&&Reflect.get?Reflect.get.bind():function(i,e,t){var n=Fu(i,e);if(n){var r=Object.getOwnPropertyDescriptor(n,e);return r.get?r.get.call(arguments.length<3?i:t):r.value}},ha.apply(null,arguments)}function Hc(i,e,t,n){var r=ha(ei(1&n?i.prototype:i),e,t);return 2&n&&typeof r=="function"?function(s){return r.apply(t,s)}:r}function Ou(i){return i.normalized?1:i.size}function ca(i){var e=0;return i.forEach(function(t){return e+=Ou(t)}),e}function Wc(i,e,t){var n=i==="VERTEX"?e.VERTEX_SHADER:e.FRAGMENT_SHADER,r=e.createShader(n);if(r===null)throw new Error("loadShader: error while creating the shader");e.shaderSource(r,t),e.compileShader(r);var s=e.getShaderParameter(r,e.COMPILE_STATUS);if(!s){var a=e.getShaderInfoLog(r);throw e.deleteShader(r),new Error(`loadShader: error while compiling the shader:
`.concat(a,`
`).concat(t))}return r}function ku(i,e){return Wc("VERTEX",i,e)}function Bu(i,e){return Wc("FRAGMENT",i,e)}function zu(i,e){var t=i.createProgram();if(t===null)throw new Error("loadProgram: error while creating the program.");var n,r;for(n=0,r=e.length;n<r;n++)i.attachShader(t,e[n]);i.linkProgram(t);var s=i.getProgramParameter(t,i.LINK_STATUS);if(!s){var a=i.getProgramInfoLog(t);throw i.deleteProgram(t),new Error("loadProgram: error while linking the program: ".concat(a))}return t}function Oc(i){var e=i.gl,t=i.buffer,n=i.program,r=i.vertexShader,s=i.fragmentShader;e.deleteShader(r),e.deleteShader(s),e.deleteProgram(n),e.deleteBuffer(t)}var kc=`#define PICKING_MODE
`,Gu=ce(ce(ce(ce(ce(ce(ce(ce({},WebGL2RenderingContext.BOOL,1),WebGL2RenderingContext.BYTE,1),WebGL2RenderingContext.UNSIGNED_BYTE,1),WebGL2RenderingContext.SHORT,2),WebGL2RenderingContext.UNSIGNED_SHORT,2),WebGL2RenderingContext.INT,4),WebGL2RenderingContext.UNSIGNED_INT,4),WebGL2RenderingContext.FLOAT,4);var Xc=function(){function i(e,t,n){yt(this,i),ce(this,"array",new Float32Array),ce(this,"constantArray",new Float32Array),ce(this,"capacity",0),ce(this,"verticesCount",0);var r=this.getDefinition();if(this.VERTICES=r.VERTICES,this.VERTEX_SHADER_SOURCE=r.VERTEX_SHADER_SOURCE,this.FRAGMENT_SHADER_SOURCE=r.FRAGMENT_SHADER_SOURCE,this.UNIFORMS=r.UNIFORMS,this.ATTRIBUTES=r.ATTRIBUTES,this.METHOD=r.METHOD,this.CONSTANT_ATTRIBUTES="CONSTANT_ATTRIBUTES"in r?r.CONSTANT_ATTRIBUTES:[],this.CONSTANT_DATA="CONSTANT_DATA"in r?r.CONSTANT_DATA:[],this.isInstanced="CONSTANT_ATTRIBUTES"in r,this.ATTRIBUTES_ITEMS_COUNT=ca(this.ATTRIBUTES),this.STRIDE=this.VERTICES*this.ATTRIBUTES_ITEMS_COUNT,this.renderer=n,this.normalProgram=this.getProgramInfo("normal",e,r.VERTEX_SHADER_SOURCE,r.FRAGMENT_SHADER_SOURCE,null),this.pickProgram=t?this.getProgramInfo("pick",e,kc+r.VERTEX_SHADER_SOURCE,kc+r.FRAGMENT_SHADER_SOURCE,t):null,this.isInstanced){var s=ca(this.CONSTANT_ATTRIBUTES);if(this.CONSTANT_DATA.length!==this.VERTICES)throw new Error("Program: error while getting constant data (expected ".concat(this.VERTICES," items, received ").concat(this.CONSTANT_DATA.length," instead)"));this.constantArray=new Float32Array(this.CONSTANT_DATA.length*s);for(var a=0;a<this.CONSTANT_DATA.length;a++){var o=this.CONSTANT_DATA[a];if(o.length!==s)throw new Error("Program: error while getting constant data (one vector has ".concat(o.length," items instead of ").concat(s,")"));for(var l=0;l<o.length;l++)this.constantArray[a*s+l]=o[l]}this.STRIDE=this.ATTRIBUTES_ITEMS_COUNT}}return xt(i,[{key:"kill",value:function(){Oc(this.normalProgram),this.pickProgram&&(Oc(this.pickProgram),this.pickProgram=null)}},{key:"getProgramInfo",value:function(t,n,r,s,a){var o=this.getDefinition(),l=n.createBuffer();if(l===null)throw new Error("Program: error while creating the WebGL buffer.");var h=ku(n,r),d=Bu(n,s),m=zu(n,[h,d]),f={};o.UNIFORMS.forEach(function(E){var _=n.getUniformLocation(m,E);_&&(f[E]=_)});var v={};o.ATTRIBUTES.forEach(function(E){v[E.name]=n.getAttribLocation(m,E.name)});var S;if("CONSTANT_ATTRIBUTES"in o&&(o.CONSTANT_ATTRIBUTES.forEach(function(E){v[E.name]=n.getAttribLocation(m,E.name)}),S=n.createBuffer(),S===null))throw new Error("Program: error while creating the WebGL constant buffer.");return{name:t,program:m,gl:n,frameBuffer:a,buffer:l,constantBuffer:S||{},uniformLocations:f,attributeLocations:v,isPicking:t==="pick",vertexShader:h,fragmentShader:d}}},{key:"bindProgram",value:function(t){var n=this,r=0,s=t.gl,a=t.buffer;this.isInstanced?(s.bindBuffer(s.ARRAY_BUFFER,t.constantBuffer),r=0,this.CONSTANT_ATTRIBUTES.forEach(function(o){return r+=n.bindAttribute(o,t,r,!1)}),s.bufferData(s.ARRAY_BUFFER,this.constantArray,s.STATIC_DRAW),s.bindBuffer(s.ARRAY_BUFFER,t.buffer),r=0,this.ATTRIBUTES.forEach(function(o){return r+=n.bindAttribute(o,t,r,!0)}),s.bufferData(s.ARRAY_BUFFER,this.array,s.DYNAMIC_DRAW)):(s.bindBuffer(s.ARRAY_BUFFER,a),r=0,this.ATTRIBUTES.forEach(function(o){return r+=n.bindAttribute(o,t,r)}),s.bufferData(s.ARRAY_BUFFER,this.array,s.DYNAMIC_DRAW)),s.bindBuffer(s.ARRAY_BUFFER,null)}},{key:"unbindProgram",value:function(t){var n=this;this.isInstanced?(this.CONSTANT_ATTRIBUTES.forEach(function(r){return n.unbindAttribute(r,t,!1)}),this.ATTRIBUTES.forEach(function(r){return n.unbindAttribute(r,t,!0)})):this.ATTRIBUTES.forEach(function(r){return n.unbindAttribute(r,t)})}},{key:"bindAttribute",value:function(t,n,r,s){var a=Gu[t.type];if(typeof a!="number")throw new Error('Program.bind: yet unsupported attribute type "'.concat(t.type,'"'));var o=n.attributeLocations[t.name],l=n.gl;if(o!==-1){l.enableVertexAttribArray(o);var h=this.isInstanced?(s?this.ATTRIBUTES_ITEMS_COUNT:ca(this.CONSTANT_ATTRIBUTES))*Float32Array.BYTES_PER_ELEMENT:this.ATTRIBUTES_ITEMS_COUNT*Float32Array.BYTES_PER_ELEMENT;if(l.vertexAttribPointer(o,t.size,t.type,t.normalized||!1,h,r),this.isInstanced&&s)if(l instanceof WebGL2RenderingContext)l.vertexAttribDivisor(o,1);else{var d=l.getExtension("ANGLE_instanced_arrays");d&&d.vertexAttribDivisorANGLE(o,1)}}return t.size*a}},{key:"unbindAttribute",value:function(t,n,r){var s=n.attributeLocations[t.name],a=n.gl;if(s!==-1&&(a.disableVertexAttribArray(s),this.isInstanced&&r))if(a instanceof WebGL2RenderingContext)a.vertexAttribDivisor(s,0);else{var o=a.getExtension("ANGLE_instanced_arrays");o&&o.vertexAttribDivisorANGLE(s,0)}}},{key:"reallocate",value:function(t){t!==this.capacity&&(this.capacity=t,this.verticesCount=this.VERTICES*t,this.array=new Float32Array(this.isInstanced?this.capacity*this.ATTRIBUTES_ITEMS_COUNT:this.verticesCount*this.ATTRIBUTES_ITEMS_COUNT))}},{key:"hasNothingToRender",value:function(){return this.verticesCount===0}},{key:"renderProgram",value:function(t,n){var r=n.gl,s=n.program;r.enable(r.BLEND),r.useProgram(s),this.setUniforms(t,n),this.drawWebGL(this.METHOD,n)}},{key:"render",value:function(t){this.hasNothingToRender()||(this.pickProgram&&(this.pickProgram.gl.viewport(0,0,t.width*t.pixelRatio/t.downSizingRatio,t.height*t.pixelRatio/t.downSizingRatio),this.bindProgram(this.pickProgram),this.renderProgram(Re(Re({},t),{},{pixelRatio:t.pixelRatio/t.downSizingRatio}),this.pickProgram),this.unbindProgram(this.pickProgram)),this.normalProgram.gl.viewport(0,0,t.width*t.pixelRatio,t.height*t.pixelRatio),this.bindProgram(this.normalProgram),this.renderProgram(t,this.normalProgram),this.unbindProgram(this.normalProgram))}},{key:"drawWebGL",value:function(t,n){var r=n.gl,s=n.frameBuffer;if(r.bindFramebuffer(r.FRAMEBUFFER,s),!this.isInstanced)r.drawArrays(t,0,this.verticesCount);else if(r instanceof WebGL2RenderingContext)r.drawArraysInstanced(t,0,this.VERTICES,this.capacity);else{var a=r.getExtension("ANGLE_instanced_arrays");a&&a.drawArraysInstancedANGLE(t,0,this.VERTICES,this.capacity)}}}])}();var Vu=function(i){function e(){return yt(this,e),Pt(this,e,arguments)}return Lt(e,i),xt(e,[{key:"kill",value:function(){Hc(e,"kill",this,3)([])}},{key:"process",value:function(n,r,s){var a=r*this.STRIDE;if(s.hidden){for(var o=a+this.STRIDE;a<o;a++)this.array[a]=0;return}return this.processVisibleItem(sa(n),a,s)}}])}(Xc);var ua=function(i){function e(){var t;yt(this,e);for(var n=arguments.length,r=new Array(n),s=0;s<n;s++)r[s]=arguments[s];return t=Pt(this,e,[].concat(r)),ce(t,"drawLabel",void 0),t}return Lt(e,i),xt(e,[{key:"kill",value:function(){Hc(e,"kill",this,3)([])}},{key:"process",value:function(n,r,s,a,o){var l=r*this.STRIDE;if(o.hidden||s.hidden||a.hidden){for(var h=l+this.STRIDE;l<h;l++)this.array[l]=0;return}return this.processVisibleItem(sa(n),l,s,a,o)}}])}(Xc);function Hu(i,e){return function(){function t(n,r,s){yt(this,t),ce(this,"drawLabel",e),this.programs=i.map(function(a){return new a(n,r,s)})}return xt(t,[{key:"reallocate",value:function(r){this.programs.forEach(function(s){return s.reallocate(r)})}},{key:"process",value:function(r,s,a,o,l){this.programs.forEach(function(h){return h.process(r,s,a,o,l)})}},{key:"render",value:function(r){this.programs.forEach(function(s){return s.render(r)})}},{key:"kill",value:function(){this.programs.forEach(function(r){return r.kill()})}}])}()}function qc(i,e,t,n,r){var s=r.edgeLabelSize,a=r.edgeLabelFont,o=r.edgeLabelWeight,l=r.edgeLabelColor.attribute?e[r.edgeLabelColor.attribute]||r.edgeLabelColor.color||"#000":r.edgeLabelColor.color,h=e.label;if(h){i.fillStyle=l,i.font="".concat(o," ").concat(s,"px ").concat(a);var d=t.size,m=n.size,f=t.x,v=t.y,S=n.x,E=n.y,_=(f+S)/2,g=(v+E)/2,I=S-f,P=E-v,C=Math.sqrt(I*I+P*P);if(!(C<d+m)){f+=I*d/C,v+=P*d/C,S-=I*m/C,E-=P*m/C,_=(f+S)/2,g=(v+E)/2,I=S-f,P=E-v,C=Math.sqrt(I*I+P*P);var H=i.measureText(h).width;if(H>C){var U="\u2026";for(h=h+U,H=i.measureText(h).width;H>C&&h.length>1;)h=h.slice(0,-2)+U,H=i.measureText(h).width;if(h.length<4)return}var N;I>0?P>0?N=Math.acos(I/C):N=Math.asin(P/C):P>0?N=Math.acos(I/C)+Math.PI:N=Math.asin(I/C)+Math.PI/2,i.save(),i.translate(_,g),i.rotate(N),i.fillText(h,-H/2,e.size/2+s),i.restore()}}}function da(i,e,t){if(e.label){var n=t.labelSize,r=t.labelFont,s=t.labelWeight,a=t.labelColor.attribute?e[t.labelColor.attribute]||t.labelColor.color||"#000":t.labelColor.color;i.fillStyle=a,i.font="".concat(s," ").concat(n,"px ").concat(r),i.fillText(e.label,e.x+e.size+3,e.y+n/3)}}function Yc(i,e,t){var n=t.labelSize,r=t.labelFont,s=t.labelWeight;i.font="".concat(s," ").concat(n,"px ").concat(r),i.fillStyle="#FFF",i.shadowOffsetX=0,i.shadowOffsetY=0,i.shadowBlur=8,i.shadowColor="#000";var a=2;if(typeof e.label=="string"){var o=i.measureText(e.label).width,l=Math.round(o+5),h=Math.round(n+2*a),d=Math.max(e.size,n/2)+a,m=Math.asin(h/2/d),f=Math.sqrt(Math.abs(Math.pow(d,2)-Math.pow(h/2,2)));i.beginPath(),i.moveTo(e.x+f,e.y+h/2),i.lineTo(e.x+d+l,e.y+h/2),i.lineTo(e.x+d+l,e.y-h/2),i.lineTo(e.x+f,e.y-h/2),i.arc(e.x,e.y,d,m,-m),i.closePath(),i.fill()}else i.beginPath(),i.arc(e.x,e.y,e.size+a,0,Math.PI*2),i.closePath(),i.fill();i.shadowOffsetX=0,i.shadowOffsetY=0,i.shadowBlur=0,da(i,e,t)}var Wu=`
precision highp float;

varying vec4 v_color;
varying vec2 v_diffVector;
varying float v_radius;

uniform float u_correctionRatio;

const vec4 transparent = vec4(0.0, 0.0, 0.0, 0.0);

void main(void) {
  float border = u_correctionRatio * 2.0;
  float dist = length(v_diffVector) - v_radius + border;

  // No antialiasing for picking mode:
  #ifdef PICKING_MODE
  if (dist > border)
    gl_FragColor = transparent;
  else
    gl_FragColor = v_color;

  #else
  float t = 0.0;
  if (dist > border)
    t = 1.0;
  else if (dist > 0.0)
    t = dist / border;

  gl_FragColor = mix(v_color, transparent, t);
  #endif
}
`,Xu=Wu,qu=`
attribute vec4 a_id;
attribute vec4 a_color;
attribute vec2 a_position;
attribute float a_size;
attribute float a_angle;

uniform mat3 u_matrix;
uniform float u_sizeRatio;
uniform float u_correctionRatio;

varying vec4 v_color;
varying vec2 v_diffVector;
varying float v_radius;
varying float v_border;

const float bias = 255.0 / 254.0;

void main() {
  float size = a_size * u_correctionRatio / u_sizeRatio * 4.0;
  vec2 diffVector = size * vec2(cos(a_angle), sin(a_angle));
  vec2 position = a_position + diffVector;
  gl_Position = vec4(
    (u_matrix * vec3(position, 1)).xy,
    0,
    1
  );

  v_diffVector = diffVector;
  v_radius = size / 2.0;

  #ifdef PICKING_MODE
  // For picking mode, we use the ID as the color:
  v_color = a_id;
  #else
  // For normal mode, we use the color:
  v_color = a_color;
  #endif

  v_color.a *= bias;
}
`,Yu=qu,Zc=WebGLRenderingContext,Bc=Zc.UNSIGNED_BYTE,la=Zc.FLOAT,Zu=["u_sizeRatio","u_correctionRatio","u_matrix"],mr=function(i){function e(){return yt(this,e),Pt(this,e,arguments)}return Lt(e,i),xt(e,[{key:"getDefinition",value:function(){return{VERTICES:3,VERTEX_SHADER_SOURCE:Yu,FRAGMENT_SHADER_SOURCE:Xu,METHOD:WebGLRenderingContext.TRIANGLES,UNIFORMS:Zu,ATTRIBUTES:[{name:"a_position",size:2,type:la},{name:"a_size",size:1,type:la},{name:"a_color",size:4,type:Bc,normalized:!0},{name:"a_id",size:4,type:Bc,normalized:!0}],CONSTANT_ATTRIBUTES:[{name:"a_angle",size:1,type:la}],CONSTANT_DATA:[[e.ANGLE_1],[e.ANGLE_2],[e.ANGLE_3]]}}},{key:"processVisibleItem",value:function(n,r,s){var a=this.array,o=wi(s.color);a[r++]=s.x,a[r++]=s.y,a[r++]=s.size,a[r++]=o,a[r++]=n}},{key:"setUniforms",value:function(n,r){var s=r.gl,a=r.uniformLocations,o=a.u_sizeRatio,l=a.u_correctionRatio,h=a.u_matrix;s.uniform1f(l,n.correctionRatio),s.uniform1f(o,n.sizeRatio),s.uniformMatrix3fv(h,!1,n.matrix)}}])}(Vu);ce(mr,"ANGLE_1",0);ce(mr,"ANGLE_2",2*Math.PI/3);ce(mr,"ANGLE_3",4*Math.PI/3);var $u=`
precision mediump float;

varying vec4 v_color;

void main(void) {
  gl_FragColor = v_color;
}
`,Ku=$u,ju=`
attribute vec2 a_position;
attribute vec2 a_normal;
attribute float a_radius;
attribute vec3 a_barycentric;

#ifdef PICKING_MODE
attribute vec4 a_id;
#else
attribute vec4 a_color;
#endif

uniform mat3 u_matrix;
uniform float u_sizeRatio;
uniform float u_correctionRatio;
uniform float u_minEdgeThickness;
uniform float u_lengthToThicknessRatio;
uniform float u_widenessToThicknessRatio;

varying vec4 v_color;

const float bias = 255.0 / 254.0;

void main() {
  float minThickness = u_minEdgeThickness;

  float normalLength = length(a_normal);
  vec2 unitNormal = a_normal / normalLength;

  // These first computations are taken from edge.vert.glsl and
  // edge.clamped.vert.glsl. Please read it to get better comments on what's
  // happening:
  float pixelsThickness = max(normalLength / u_sizeRatio, minThickness);
  float webGLThickness = pixelsThickness * u_correctionRatio;
  float webGLNodeRadius = a_radius * 2.0 * u_correctionRatio / u_sizeRatio;
  float webGLArrowHeadLength = webGLThickness * u_lengthToThicknessRatio * 2.0;
  float webGLArrowHeadThickness = webGLThickness * u_widenessToThicknessRatio;

  float da = a_barycentric.x;
  float db = a_barycentric.y;
  float dc = a_barycentric.z;

  vec2 delta = vec2(
      da * (webGLNodeRadius * unitNormal.y)
    + db * ((webGLNodeRadius + webGLArrowHeadLength) * unitNormal.y + webGLArrowHeadThickness * unitNormal.x)
    + dc * ((webGLNodeRadius + webGLArrowHeadLength) * unitNormal.y - webGLArrowHeadThickness * unitNormal.x),

      da * (-webGLNodeRadius * unitNormal.x)
    + db * (-(webGLNodeRadius + webGLArrowHeadLength) * unitNormal.x + webGLArrowHeadThickness * unitNormal.y)
    + dc * (-(webGLNodeRadius + webGLArrowHeadLength) * unitNormal.x - webGLArrowHeadThickness * unitNormal.y)
  );

  vec2 position = (u_matrix * vec3(a_position + delta, 1)).xy;

  gl_Position = vec4(position, 0, 1);

  #ifdef PICKING_MODE
  // For picking mode, we use the ID as the color:
  v_color = a_id;
  #else
  // For normal mode, we use the color:
  v_color = a_color;
  #endif

  v_color.a *= bias;
}
`,Ju=ju,$c=WebGLRenderingContext,zc=$c.UNSIGNED_BYTE,Fr=$c.FLOAT,Qu=["u_matrix","u_sizeRatio","u_correctionRatio","u_minEdgeThickness","u_lengthToThicknessRatio","u_widenessToThicknessRatio"],Kc={extremity:"target",lengthToThicknessRatio:2.5,widenessToThicknessRatio:2};function jc(i){var e=Re(Re({},Kc),i||{});return function(t){function n(){return yt(this,n),Pt(this,n,arguments)}return Lt(n,t),xt(n,[{key:"getDefinition",value:function(){return{VERTICES:3,VERTEX_SHADER_SOURCE:Ju,FRAGMENT_SHADER_SOURCE:Ku,METHOD:WebGLRenderingContext.TRIANGLES,UNIFORMS:Qu,ATTRIBUTES:[{name:"a_position",size:2,type:Fr},{name:"a_normal",size:2,type:Fr},{name:"a_radius",size:1,type:Fr},{name:"a_color",size:4,type:zc,normalized:!0},{name:"a_id",size:4,type:zc,normalized:!0}],CONSTANT_ATTRIBUTES:[{name:"a_barycentric",size:3,type:Fr}],CONSTANT_DATA:[[1,0,0],[0,1,0],[0,0,1]]}}},{key:"processVisibleItem",value:function(s,a,o,l,h){if(e.extremity==="source"){var d=[l,o];o=d[0],l=d[1]}var m=h.size||1,f=l.size||1,v=o.x,S=o.y,E=l.x,_=l.y,g=wi(h.color),I=E-v,P=_-S,C=I*I+P*P,H=0,U=0;C&&(C=1/Math.sqrt(C),H=-P*C*m,U=I*C*m);var N=this.array;N[a++]=E,N[a++]=_,N[a++]=-H,N[a++]=-U,N[a++]=f,N[a++]=g,N[a++]=s}},{key:"setUniforms",value:function(s,a){var o=a.gl,l=a.uniformLocations,h=l.u_matrix,d=l.u_sizeRatio,m=l.u_correctionRatio,f=l.u_minEdgeThickness,v=l.u_lengthToThicknessRatio,S=l.u_widenessToThicknessRatio;o.uniformMatrix3fv(h,!1,s.matrix),o.uniform1f(d,s.sizeRatio),o.uniform1f(m,s.correctionRatio),o.uniform1f(f,s.minEdgeThickness),o.uniform1f(v,e.lengthToThicknessRatio),o.uniform1f(S,e.widenessToThicknessRatio)}}])}(ua)}var Ny=jc();var ed=`
precision mediump float;

varying vec4 v_color;
varying vec2 v_normal;
varying float v_thickness;
varying float v_feather;

const vec4 transparent = vec4(0.0, 0.0, 0.0, 0.0);

void main(void) {
  // We only handle antialiasing for normal mode:
  #ifdef PICKING_MODE
  gl_FragColor = v_color;
  #else
  float dist = length(v_normal) * v_thickness;

  float t = smoothstep(
    v_thickness - v_feather,
    v_thickness,
    dist
  );

  gl_FragColor = mix(v_color, transparent, t);
  #endif
}
`,Jc=ed,td=`
attribute vec4 a_id;
attribute vec4 a_color;
attribute vec2 a_normal;
attribute float a_normalCoef;
attribute vec2 a_positionStart;
attribute vec2 a_positionEnd;
attribute float a_positionCoef;
attribute float a_radius;
attribute float a_radiusCoef;

uniform mat3 u_matrix;
uniform float u_zoomRatio;
uniform float u_sizeRatio;
uniform float u_pixelRatio;
uniform float u_correctionRatio;
uniform float u_minEdgeThickness;
uniform float u_lengthToThicknessRatio;
uniform float u_feather;

varying vec4 v_color;
varying vec2 v_normal;
varying float v_thickness;
varying float v_feather;

const float bias = 255.0 / 254.0;

void main() {
  float minThickness = u_minEdgeThickness;

  float radius = a_radius * a_radiusCoef;
  vec2 normal = a_normal * a_normalCoef;
  vec2 position = a_positionStart * (1.0 - a_positionCoef) + a_positionEnd * a_positionCoef;

  float normalLength = length(normal);
  vec2 unitNormal = normal / normalLength;

  // These first computations are taken from edge.vert.glsl. Please read it to
  // get better comments on what's happening:
  float pixelsThickness = max(normalLength, minThickness * u_sizeRatio);
  float webGLThickness = pixelsThickness * u_correctionRatio / u_sizeRatio;

  // Here, we move the point to leave space for the arrow head:
  float direction = sign(radius);
  float webGLNodeRadius = direction * radius * 2.0 * u_correctionRatio / u_sizeRatio;
  float webGLArrowHeadLength = webGLThickness * u_lengthToThicknessRatio * 2.0;

  vec2 compensationVector = vec2(-direction * unitNormal.y, direction * unitNormal.x) * (webGLNodeRadius + webGLArrowHeadLength);

  // Here is the proper position of the vertex
  gl_Position = vec4((u_matrix * vec3(position + unitNormal * webGLThickness + compensationVector, 1)).xy, 0, 1);

  v_thickness = webGLThickness / u_zoomRatio;

  v_normal = unitNormal;

  v_feather = u_feather * u_correctionRatio / u_zoomRatio / u_pixelRatio * 2.0;

  #ifdef PICKING_MODE
  // For picking mode, we use the ID as the color:
  v_color = a_id;
  #else
  // For normal mode, we use the color:
  v_color = a_color;
  #endif

  v_color.a *= bias;
}
`,nd=td,Qc=WebGLRenderingContext,Gc=Qc.UNSIGNED_BYTE,ni=Qc.FLOAT,id=["u_matrix","u_zoomRatio","u_sizeRatio","u_correctionRatio","u_pixelRatio","u_feather","u_minEdgeThickness","u_lengthToThicknessRatio"],rd={lengthToThicknessRatio:Kc.lengthToThicknessRatio};function el(i){var e=Re(Re({},rd),i||{});return function(t){function n(){return yt(this,n),Pt(this,n,arguments)}return Lt(n,t),xt(n,[{key:"getDefinition",value:function(){return{VERTICES:6,VERTEX_SHADER_SOURCE:nd,FRAGMENT_SHADER_SOURCE:Jc,METHOD:WebGLRenderingContext.TRIANGLES,UNIFORMS:id,ATTRIBUTES:[{name:"a_positionStart",size:2,type:ni},{name:"a_positionEnd",size:2,type:ni},{name:"a_normal",size:2,type:ni},{name:"a_color",size:4,type:Gc,normalized:!0},{name:"a_id",size:4,type:Gc,normalized:!0},{name:"a_radius",size:1,type:ni}],CONSTANT_ATTRIBUTES:[{name:"a_positionCoef",size:1,type:ni},{name:"a_normalCoef",size:1,type:ni},{name:"a_radiusCoef",size:1,type:ni}],CONSTANT_DATA:[[0,1,0],[0,-1,0],[1,1,1],[1,1,1],[0,-1,0],[1,-1,-1]]}}},{key:"processVisibleItem",value:function(s,a,o,l,h){var d=h.size||1,m=o.x,f=o.y,v=l.x,S=l.y,E=wi(h.color),_=v-m,g=S-f,I=l.size||1,P=_*_+g*g,C=0,H=0;P&&(P=1/Math.sqrt(P),C=-g*P*d,H=_*P*d);var U=this.array;U[a++]=m,U[a++]=f,U[a++]=v,U[a++]=S,U[a++]=C,U[a++]=H,U[a++]=E,U[a++]=s,U[a++]=I}},{key:"setUniforms",value:function(s,a){var o=a.gl,l=a.uniformLocations,h=l.u_matrix,d=l.u_zoomRatio,m=l.u_feather,f=l.u_pixelRatio,v=l.u_correctionRatio,S=l.u_sizeRatio,E=l.u_minEdgeThickness,_=l.u_lengthToThicknessRatio;o.uniformMatrix3fv(h,!1,s.matrix),o.uniform1f(d,s.zoomRatio),o.uniform1f(S,s.sizeRatio),o.uniform1f(v,s.correctionRatio),o.uniform1f(f,s.pixelRatio),o.uniform1f(m,s.antiAliasingFeather),o.uniform1f(E,s.minEdgeThickness),o.uniform1f(_,e.lengthToThicknessRatio)}}])}(ua)}var Uy=el();function sd(i){return Hu([el(i),jc(i)])}var ad=sd(),tl=ad,od=`
attribute vec4 a_id;
attribute vec4 a_color;
attribute vec2 a_normal;
attribute float a_normalCoef;
attribute vec2 a_positionStart;
attribute vec2 a_positionEnd;
attribute float a_positionCoef;

uniform mat3 u_matrix;
uniform float u_sizeRatio;
uniform float u_zoomRatio;
uniform float u_pixelRatio;
uniform float u_correctionRatio;
uniform float u_minEdgeThickness;
uniform float u_feather;

varying vec4 v_color;
varying vec2 v_normal;
varying float v_thickness;
varying float v_feather;

const float bias = 255.0 / 254.0;

void main() {
  float minThickness = u_minEdgeThickness;

  vec2 normal = a_normal * a_normalCoef;
  vec2 position = a_positionStart * (1.0 - a_positionCoef) + a_positionEnd * a_positionCoef;

  float normalLength = length(normal);
  vec2 unitNormal = normal / normalLength;

  // We require edges to be at least "minThickness" pixels thick *on screen*
  // (so we need to compensate the size ratio):
  float pixelsThickness = max(normalLength, minThickness * u_sizeRatio);

  // Then, we need to retrieve the normalized thickness of the edge in the WebGL
  // referential (in a ([0, 1], [0, 1]) space), using our "magic" correction
  // ratio:
  float webGLThickness = pixelsThickness * u_correctionRatio / u_sizeRatio;

  // Here is the proper position of the vertex
  gl_Position = vec4((u_matrix * vec3(position + unitNormal * webGLThickness, 1)).xy, 0, 1);

  // For the fragment shader though, we need a thickness that takes the "magic"
  // correction ratio into account (as in webGLThickness), but so that the
  // antialiasing effect does not depend on the zoom level. So here's yet
  // another thickness version:
  v_thickness = webGLThickness / u_zoomRatio;

  v_normal = unitNormal;

  v_feather = u_feather * u_correctionRatio / u_zoomRatio / u_pixelRatio * 2.0;

  #ifdef PICKING_MODE
  // For picking mode, we use the ID as the color:
  v_color = a_id;
  #else
  // For normal mode, we use the color:
  v_color = a_color;
  #endif

  v_color.a *= bias;
}
`,cd=od,nl=WebGLRenderingContext,Vc=nl.UNSIGNED_BYTE,pr=nl.FLOAT,ld=["u_matrix","u_zoomRatio","u_sizeRatio","u_correctionRatio","u_pixelRatio","u_feather","u_minEdgeThickness"],il=function(i){function e(){return yt(this,e),Pt(this,e,arguments)}return Lt(e,i),xt(e,[{key:"getDefinition",value:function(){return{VERTICES:6,VERTEX_SHADER_SOURCE:cd,FRAGMENT_SHADER_SOURCE:Jc,METHOD:WebGLRenderingContext.TRIANGLES,UNIFORMS:ld,ATTRIBUTES:[{name:"a_positionStart",size:2,type:pr},{name:"a_positionEnd",size:2,type:pr},{name:"a_normal",size:2,type:pr},{name:"a_color",size:4,type:Vc,normalized:!0},{name:"a_id",size:4,type:Vc,normalized:!0}],CONSTANT_ATTRIBUTES:[{name:"a_positionCoef",size:1,type:pr},{name:"a_normalCoef",size:1,type:pr}],CONSTANT_DATA:[[0,1],[0,-1],[1,1],[1,1],[0,-1],[1,-1]]}}},{key:"processVisibleItem",value:function(n,r,s,a,o){var l=o.size||1,h=s.x,d=s.y,m=a.x,f=a.y,v=wi(o.color),S=m-h,E=f-d,_=S*S+E*E,g=0,I=0;_&&(_=1/Math.sqrt(_),g=-E*_*l,I=S*_*l);var P=this.array;P[r++]=h,P[r++]=d,P[r++]=m,P[r++]=f,P[r++]=g,P[r++]=I,P[r++]=v,P[r++]=n}},{key:"setUniforms",value:function(n,r){var s=r.gl,a=r.uniformLocations,o=a.u_matrix,l=a.u_zoomRatio,h=a.u_feather,d=a.u_pixelRatio,m=a.u_correctionRatio,f=a.u_sizeRatio,v=a.u_minEdgeThickness;s.uniformMatrix3fv(o,!1,n.matrix),s.uniform1f(l,n.zoomRatio),s.uniform1f(f,n.sizeRatio),s.uniform1f(m,n.correctionRatio),s.uniform1f(d,n.pixelRatio),s.uniform1f(h,n.antiAliasingFeather),s.uniform1f(v,n.minEdgeThickness)}}])}(ua);var pl=dr(pa()),Br=function(i){function e(){var t;return yt(this,e),t=Pt(this,e),t.rawEmitter=t,t}return Lt(e,i),xt(e)}(pl.EventEmitter);var _l=dr(ma());var gd=function(e){return e},vd=function(e){return e*e},_d=function(e){return e*(2-e)},yd=function(e){return(e*=2)<1?.5*e*e:-.5*(--e*(e-2)-1)},xd=function(e){return e*e*e},bd=function(e){return--e*e*e+1},Sd=function(e){return(e*=2)<1?.5*e*e*e:.5*((e-=2)*e*e+2)},yl={linear:gd,quadraticIn:vd,quadraticOut:_d,quadraticInOut:yd,cubicIn:xd,cubicOut:bd,cubicInOut:Sd},xl={easing:"quadraticInOut",duration:150};function Xt(){return Float32Array.of(1,0,0,0,1,0,0,0,1)}function zr(i,e,t){return i[0]=e,i[4]=typeof t=="number"?t:e,i}function gl(i,e){var t=Math.sin(e),n=Math.cos(e);return i[0]=n,i[1]=t,i[3]=-t,i[4]=n,i}function vl(i,e,t){return i[6]=e,i[7]=t,i}function zn(i,e){var t=i[0],n=i[1],r=i[2],s=i[3],a=i[4],o=i[5],l=i[6],h=i[7],d=i[8],m=e[0],f=e[1],v=e[2],S=e[3],E=e[4],_=e[5],g=e[6],I=e[7],P=e[8];return i[0]=m*t+f*s+v*l,i[1]=m*n+f*a+v*h,i[2]=m*r+f*o+v*d,i[3]=S*t+E*s+_*l,i[4]=S*n+E*a+_*h,i[5]=S*r+E*o+_*d,i[6]=g*t+I*s+P*l,i[7]=g*n+I*a+P*h,i[8]=g*r+I*o+P*d,i}function Gr(i,e){var t=arguments.length>2&&arguments[2]!==void 0?arguments[2]:1,n=i[0],r=i[1],s=i[3],a=i[4],o=i[6],l=i[7],h=e.x,d=e.y;return{x:h*n+d*s+o*t,y:h*r+d*a+l*t}}function Md(i,e){var t=i.height/i.width,n=e.height/e.width;return t<1&&n>1||t>1&&n<1?1:Math.min(Math.max(n,1/n),Math.max(1/t,t))}function Ti(i,e,t,n,r){var s=i.angle,a=i.ratio,o=i.x,l=i.y,h=e.width,d=e.height,m=Xt(),f=Math.min(h,d)-2*n,v=Md(e,t);return r?(zn(m,vl(Xt(),o,l)),zn(m,zr(Xt(),a)),zn(m,gl(Xt(),s)),zn(m,zr(Xt(),h/f/2/v,d/f/2/v))):(zn(m,zr(Xt(),2*(f/h)*v,2*(f/d)*v)),zn(m,gl(Xt(),-s)),zn(m,zr(Xt(),1/a)),zn(m,vl(Xt(),-o,-l))),m}function bl(i,e,t){var n=Gr(i,{x:Math.cos(e.angle),y:Math.sin(e.angle)},0),r=n.x,s=n.y;return 1/Math.sqrt(Math.pow(r,2)+Math.pow(s,2))/t.width}function Sl(i){if(!i.order)return{x:[0,1],y:[0,1]};var e=1/0,t=-1/0,n=1/0,r=-1/0;return i.forEachNode(function(s,a){var o=a.x,l=a.y;o<e&&(e=o),o>t&&(t=o),l<n&&(n=l),l>r&&(r=l)}),{x:[e,t],y:[n,r]}}function Ml(i){if(!(0,_l.default)(i))throw new Error("Sigma: invalid graph instance.");i.forEachNode(function(e,t){if(!Number.isFinite(t.x)||!Number.isFinite(t.y))throw new Error("Sigma: Coordinates of node ".concat(e," are invalid. A node must have a numeric 'x' and 'y' attribute."))})}function wl(i,e,t){var n=document.createElement(i);if(e)for(var r in e)n.style[r]=e[r];if(t)for(var s in t)n.setAttribute(s,t[s]);return n}function ga(){return typeof window.devicePixelRatio<"u"?window.devicePixelRatio:1}function va(i,e,t){return t.sort(function(n,r){var s=e(n)||0,a=e(r)||0;return s<a?-1:s>a?1:0})}function _a(i){var e=Bn(i.x,2),t=e[0],n=e[1],r=Bn(i.y,2),s=r[0],a=r[1],o=Math.max(n-t,a-s),l=(n+t)/2,h=(a+s)/2;(o===0||Math.abs(o)===1/0||isNaN(o))&&(o=1),isNaN(l)&&(l=0),isNaN(h)&&(h=0);var d=function(f){return{x:.5+(f.x-l)/o,y:.5+(f.y-h)/o}};return d.applyTo=function(m){m.x=.5+(m.x-l)/o,m.y=.5+(m.y-h)/o},d.inverse=function(m){return{x:l+o*(m.x-.5),y:h+o*(m.y-.5)}},d.ratio=o,d}function Vr(i){"@babel/helpers - typeof";return Vr=typeof Symbol=="function"&&typeof Symbol.iterator=="symbol"?function(e){return typeof e}:function(e){return e&&typeof Symbol=="function"&&e.constructor===Symbol&&e!==Symbol.prototype?"symbol":typeof e},Vr(i)}function ya(i,e){var t=e.size;if(t!==0){var n=i.length;i.length+=t;var r=0;e.forEach(function(s){i[n+r]=s,r++})}}function Hr(i){i=i||{};for(var e=0,t=arguments.length<=1?0:arguments.length-1;e<t;e++){var n=e+1<1||arguments.length<=e+1?void 0:arguments[e+1];n&&Object.assign(i,n)}return i}var Wr={hideEdgesOnMove:!1,hideLabelsOnMove:!1,renderLabels:!0,renderEdgeLabels:!1,enableEdgeEvents:!1,defaultNodeColor:"#999",defaultNodeType:"circle",defaultEdgeColor:"#ccc",defaultEdgeType:"line",labelFont:"Arial",labelSize:14,labelWeight:"normal",labelColor:{color:"#000"},edgeLabelFont:"Arial",edgeLabelSize:14,edgeLabelWeight:"normal",edgeLabelColor:{attribute:"color"},stagePadding:30,defaultDrawEdgeLabel:qc,defaultDrawNodeLabel:da,defaultDrawNodeHover:Yc,minEdgeThickness:1.7,antiAliasingFeather:1,dragTimeout:100,draggedEventsTolerance:3,inertiaDuration:200,inertiaRatio:3,zoomDuration:250,zoomingRatio:1.7,doubleClickTimeout:300,doubleClickZoomingRatio:2.2,doubleClickZoomingDuration:200,tapMoveTolerance:10,zoomToSizeRatioFunction:Math.sqrt,itemSizesReference:"screen",autoRescale:!0,autoCenter:!0,labelDensity:1,labelGridCellSize:100,labelRenderedSizeThreshold:6,nodeReducer:null,edgeReducer:null,zIndex:!1,minCameraRatio:null,maxCameraRatio:null,enableCameraZooming:!0,enableCameraPanning:!0,enableCameraRotation:!0,cameraPanBoundaries:null,allowInvalidContainer:!1,nodeProgramClasses:{},nodeHoverProgramClasses:{},edgeProgramClasses:{}},wd={circle:mr},Ed={arrow:tl,line:il};function Xr(i){if(typeof i.labelDensity!="number"||i.labelDensity<0)throw new Error("Settings: invalid `labelDensity`. Expecting a positive number.");var e=i.minCameraRatio,t=i.maxCameraRatio;if(typeof e=="number"&&typeof t=="number"&&t<e)throw new Error("Settings: invalid camera ratio boundaries. Expecting `maxCameraRatio` to be greater than `minCameraRatio`.")}function El(i){var e=Hr({},Wr,i);return e.nodeProgramClasses=Hr({},wd,e.nodeProgramClasses),e.edgeProgramClasses=Hr({},Ed,e.edgeProgramClasses),e}var e0=dr(pa()),t0=dr(ma()),qr=1.5,Tl=function(i){function e(){var t;return yt(this,e),t=Pt(this,e),ce(t,"x",.5),ce(t,"y",.5),ce(t,"angle",0),ce(t,"ratio",1),ce(t,"minRatio",null),ce(t,"maxRatio",null),ce(t,"enabledZooming",!0),ce(t,"enabledPanning",!0),ce(t,"enabledRotation",!0),ce(t,"clean",null),ce(t,"nextFrame",null),ce(t,"previousState",null),ce(t,"enabled",!0),t.previousState=t.getState(),t}return Lt(e,i),xt(e,[{key:"enable",value:function(){return this.enabled=!0,this}},{key:"disable",value:function(){return this.enabled=!1,this}},{key:"getState",value:function(){return{x:this.x,y:this.y,angle:this.angle,ratio:this.ratio}}},{key:"hasState",value:function(n){return this.x===n.x&&this.y===n.y&&this.ratio===n.ratio&&this.angle===n.angle}},{key:"getPreviousState",value:function(){var n=this.previousState;return n?{x:n.x,y:n.y,angle:n.angle,ratio:n.ratio}:null}},{key:"getBoundedRatio",value:function(n){var r=n;return typeof this.minRatio=="number"&&(r=Math.max(r,this.minRatio)),typeof this.maxRatio=="number"&&(r=Math.min(r,this.maxRatio)),r}},{key:"validateState",value:function(n){var r={};return this.enabledPanning&&typeof n.x=="number"&&(r.x=n.x),this.enabledPanning&&typeof n.y=="number"&&(r.y=n.y),this.enabledZooming&&typeof n.ratio=="number"&&(r.ratio=this.getBoundedRatio(n.ratio)),this.enabledRotation&&typeof n.angle=="number"&&(r.angle=n.angle),this.clean?this.clean(Re(Re({},this.getState()),r)):r}},{key:"isAnimated",value:function(){return!!this.nextFrame}},{key:"setState",value:function(n){if(!this.enabled)return this;this.previousState=this.getState();var r=this.validateState(n);return typeof r.x=="number"&&(this.x=r.x),typeof r.y=="number"&&(this.y=r.y),typeof r.ratio=="number"&&(this.ratio=r.ratio),typeof r.angle=="number"&&(this.angle=r.angle),this.hasState(this.previousState)||this.emit("updated",this.getState()),this}},{key:"updateState",value:function(n){return this.setState(n(this.getState())),this}},{key:"animate",value:function(n){var r=this,s=arguments.length>1&&arguments[1]!==void 0?arguments[1]:{},a=arguments.length>2?arguments[2]:void 0;if(!a)return new Promise(function(v){return r.animate(n,s,v)});if(this.enabled){var o=Re(Re({},xl),s),l=this.validateState(n),h=typeof o.easing=="function"?o.easing:yl[o.easing],d=Date.now(),m=this.getState(),f=function(){var S=(Date.now()-d)/o.duration;if(S>=1){r.nextFrame=null,r.setState(l),r.animationCallback&&(r.animationCallback.call(null),r.animationCallback=void 0);return}var E=h(S),_={};typeof l.x=="number"&&(_.x=m.x+(l.x-m.x)*E),typeof l.y=="number"&&(_.y=m.y+(l.y-m.y)*E),r.enabledRotation&&typeof l.angle=="number"&&(_.angle=m.angle+(l.angle-m.angle)*E),typeof l.ratio=="number"&&(_.ratio=m.ratio+(l.ratio-m.ratio)*E),r.setState(_),r.nextFrame=requestAnimationFrame(f)};this.nextFrame?(cancelAnimationFrame(this.nextFrame),this.animationCallback&&this.animationCallback.call(null),this.nextFrame=requestAnimationFrame(f)):f(),this.animationCallback=a}}},{key:"animatedZoom",value:function(n){return n?typeof n=="number"?this.animate({ratio:this.ratio/n}):this.animate({ratio:this.ratio/(n.factor||qr)},n):this.animate({ratio:this.ratio/qr})}},{key:"animatedUnzoom",value:function(n){return n?typeof n=="number"?this.animate({ratio:this.ratio*n}):this.animate({ratio:this.ratio*(n.factor||qr)},n):this.animate({ratio:this.ratio*qr})}},{key:"animatedReset",value:function(n){return this.animate({x:.5,y:.5,ratio:1,angle:0},n)}},{key:"copy",value:function(){return e.from(this.getState())}}],[{key:"from",value:function(n){var r=new e;return r.setState(n)}}])}(Br);function Qt(i,e){var t=e.getBoundingClientRect();return{x:i.clientX-t.left,y:i.clientY-t.top}}function vn(i,e){var t=Re(Re({},Qt(i,e)),{},{sigmaDefaultPrevented:!1,preventSigmaDefault:function(){t.sigmaDefaultPrevented=!0},original:i});return t}function gr(i){var e="x"in i?i:Re(Re({},i.touches[0]||i.previousTouches[0]),{},{original:i.original,sigmaDefaultPrevented:i.sigmaDefaultPrevented,preventSigmaDefault:function(){i.sigmaDefaultPrevented=!0,e.sigmaDefaultPrevented=!0}});return e}function Td(i,e){return Re(Re({},vn(i,e)),{},{delta:Il(i)})}var Ad=2;function Yr(i){for(var e=[],t=0,n=Math.min(i.length,Ad);t<n;t++)e.push(i[t]);return e}function vr(i,e,t){var n={touches:Yr(i.touches).map(function(r){return Qt(r,t)}),previousTouches:e.map(function(r){return Qt(r,t)}),sigmaDefaultPrevented:!1,preventSigmaDefault:function(){n.sigmaDefaultPrevented=!0},original:i};return n}function Il(i){if(typeof i.deltaY<"u")return i.deltaY*-3/360;if(typeof i.detail<"u")return i.detail/-9;throw new Error("Captor: could not extract delta from event.")}var Dl=function(i){function e(t,n){var r;return yt(this,e),r=Pt(this,e),r.container=t,r.renderer=n,r}return Lt(e,i),xt(e)}(Br),Cd=["doubleClickTimeout","doubleClickZoomingDuration","doubleClickZoomingRatio","dragTimeout","draggedEventsTolerance","inertiaDuration","inertiaRatio","zoomDuration","zoomingRatio"],Rd=Cd.reduce(function(i,e){return Re(Re({},i),{},ce({},e,Wr[e]))},{}),Pd=function(i){function e(t,n){var r;return yt(this,e),r=Pt(this,e,[t,n]),ce(r,"enabled",!0),ce(r,"draggedEvents",0),ce(r,"downStartTime",null),ce(r,"lastMouseX",null),ce(r,"lastMouseY",null),ce(r,"isMouseDown",!1),ce(r,"isMoving",!1),ce(r,"movingTimeout",null),ce(r,"startCameraState",null),ce(r,"clicks",0),ce(r,"doubleClickTimeout",null),ce(r,"currentWheelDirection",0),ce(r,"settings",Rd),r.handleClick=r.handleClick.bind(r),r.handleRightClick=r.handleRightClick.bind(r),r.handleDown=r.handleDown.bind(r),r.handleUp=r.handleUp.bind(r),r.handleMove=r.handleMove.bind(r),r.handleWheel=r.handleWheel.bind(r),r.handleLeave=r.handleLeave.bind(r),r.handleEnter=r.handleEnter.bind(r),t.addEventListener("click",r.handleClick,{capture:!1}),t.addEventListener("contextmenu",r.handleRightClick,{capture:!1}),t.addEventListener("mousedown",r.handleDown,{capture:!1}),t.addEventListener("wheel",r.handleWheel,{capture:!1}),t.addEventListener("mouseleave",r.handleLeave,{capture:!1}),t.addEventListener("mouseenter",r.handleEnter,{capture:!1}),document.addEventListener("mousemove",r.handleMove,{capture:!1}),document.addEventListener("mouseup",r.handleUp,{capture:!1}),r}return Lt(e,i),xt(e,[{key:"kill",value:function(){var n=this.container;n.removeEventListener("click",this.handleClick),n.removeEventListener("contextmenu",this.handleRightClick),n.removeEventListener("mousedown",this.handleDown),n.removeEventListener("wheel",this.handleWheel),n.removeEventListener("mouseleave",this.handleLeave),n.removeEventListener("mouseenter",this.handleEnter),document.removeEventListener("mousemove",this.handleMove),document.removeEventListener("mouseup",this.handleUp)}},{key:"handleClick",value:function(n){var r=this;if(this.enabled){if(this.clicks++,this.clicks===2)return this.clicks=0,typeof this.doubleClickTimeout=="number"&&(clearTimeout(this.doubleClickTimeout),this.doubleClickTimeout=null),this.handleDoubleClick(n);setTimeout(function(){r.clicks=0,r.doubleClickTimeout=null},this.settings.doubleClickTimeout),this.draggedEvents<this.settings.draggedEventsTolerance&&this.emit("click",vn(n,this.container))}}},{key:"handleRightClick",value:function(n){this.enabled&&this.emit("rightClick",vn(n,this.container))}},{key:"handleDoubleClick",value:function(n){if(this.enabled){n.preventDefault(),n.stopPropagation();var r=vn(n,this.container);if(this.emit("doubleClick",r),!r.sigmaDefaultPrevented){var s=this.renderer.getCamera(),a=s.getBoundedRatio(s.getState().ratio/this.settings.doubleClickZoomingRatio);s.animate(this.renderer.getViewportZoomedState(Qt(n,this.container),a),{easing:"quadraticInOut",duration:this.settings.doubleClickZoomingDuration})}}}},{key:"handleDown",value:function(n){if(this.enabled){if(n.button===0){this.startCameraState=this.renderer.getCamera().getState();var r=Qt(n,this.container),s=r.x,a=r.y;this.lastMouseX=s,this.lastMouseY=a,this.draggedEvents=0,this.downStartTime=Date.now(),this.isMouseDown=!0}this.emit("mousedown",vn(n,this.container))}}},{key:"handleUp",value:function(n){var r=this;if(!(!this.enabled||!this.isMouseDown)){var s=this.renderer.getCamera();this.isMouseDown=!1,typeof this.movingTimeout=="number"&&(clearTimeout(this.movingTimeout),this.movingTimeout=null);var a=Qt(n,this.container),o=a.x,l=a.y,h=s.getState(),d=s.getPreviousState()||{x:0,y:0};this.isMoving?s.animate({x:h.x+this.settings.inertiaRatio*(h.x-d.x),y:h.y+this.settings.inertiaRatio*(h.y-d.y)},{duration:this.settings.inertiaDuration,easing:"quadraticOut"}):(this.lastMouseX!==o||this.lastMouseY!==l)&&s.setState({x:h.x,y:h.y}),this.isMoving=!1,setTimeout(function(){var m=r.draggedEvents>0;r.draggedEvents=0,m&&r.renderer.getSetting("hideEdgesOnMove")&&r.renderer.refresh()},0),this.emit("mouseup",vn(n,this.container))}}},{key:"handleMove",value:function(n){var r=this;if(this.enabled){var s=vn(n,this.container);if(this.emit("mousemovebody",s),(n.target===this.container||n.composedPath()[0]===this.container)&&this.emit("mousemove",s),!s.sigmaDefaultPrevented&&this.isMouseDown){this.isMoving=!0,this.draggedEvents++,typeof this.movingTimeout=="number"&&clearTimeout(this.movingTimeout),this.movingTimeout=window.setTimeout(function(){r.movingTimeout=null,r.isMoving=!1},this.settings.dragTimeout);var a=this.renderer.getCamera(),o=Qt(n,this.container),l=o.x,h=o.y,d=this.renderer.viewportToFramedGraph({x:this.lastMouseX,y:this.lastMouseY}),m=this.renderer.viewportToFramedGraph({x:l,y:h}),f=d.x-m.x,v=d.y-m.y,S=a.getState(),E=S.x+f,_=S.y+v;a.setState({x:E,y:_}),this.lastMouseX=l,this.lastMouseY=h,n.preventDefault(),n.stopPropagation()}}}},{key:"handleLeave",value:function(n){this.emit("mouseleave",vn(n,this.container))}},{key:"handleEnter",value:function(n){this.emit("mouseenter",vn(n,this.container))}},{key:"handleWheel",value:function(n){var r=this,s=this.renderer.getCamera();if(!(!this.enabled||!s.enabledZooming)){var a=Il(n);if(a){var o=Td(n,this.container);if(this.emit("wheel",o),o.sigmaDefaultPrevented){n.preventDefault(),n.stopPropagation();return}var l=s.getState().ratio,h=a>0?1/this.settings.zoomingRatio:this.settings.zoomingRatio,d=s.getBoundedRatio(l*h),m=a>0?1:-1,f=Date.now();l!==d&&(n.preventDefault(),n.stopPropagation(),!(this.currentWheelDirection===m&&this.lastWheelTriggerTime&&f-this.lastWheelTriggerTime<this.settings.zoomDuration/5)&&(s.animate(this.renderer.getViewportZoomedState(Qt(n,this.container),d),{easing:"quadraticOut",duration:this.settings.zoomDuration},function(){r.currentWheelDirection=0}),this.currentWheelDirection=m,this.lastWheelTriggerTime=f))}}}},{key:"setSettings",value:function(n){this.settings=n}}])}(Dl),Ld=["dragTimeout","inertiaDuration","inertiaRatio","doubleClickTimeout","doubleClickZoomingRatio","doubleClickZoomingDuration","tapMoveTolerance"],Id=Ld.reduce(function(i,e){return Re(Re({},i),{},ce({},e,Wr[e]))},{}),Dd=function(i){function e(t,n){var r;return yt(this,e),r=Pt(this,e,[t,n]),ce(r,"enabled",!0),ce(r,"isMoving",!1),ce(r,"hasMoved",!1),ce(r,"touchMode",0),ce(r,"startTouchesPositions",[]),ce(r,"lastTouches",[]),ce(r,"lastTap",null),ce(r,"settings",Id),r.handleStart=r.handleStart.bind(r),r.handleLeave=r.handleLeave.bind(r),r.handleMove=r.handleMove.bind(r),t.addEventListener("touchstart",r.handleStart,{capture:!1}),t.addEventListener("touchcancel",r.handleLeave,{capture:!1}),document.addEventListener("touchend",r.handleLeave,{capture:!1,passive:!1}),document.addEventListener("touchmove",r.handleMove,{capture:!1,passive:!1}),r}return Lt(e,i),xt(e,[{key:"kill",value:function(){var n=this.container;n.removeEventListener("touchstart",this.handleStart),n.removeEventListener("touchcancel",this.handleLeave),document.removeEventListener("touchend",this.handleLeave),document.removeEventListener("touchmove",this.handleMove)}},{key:"getDimensions",value:function(){return{width:this.container.offsetWidth,height:this.container.offsetHeight}}},{key:"handleStart",value:function(n){var r=this;if(this.enabled){n.preventDefault();var s=Yr(n.touches);if(this.touchMode=s.length,this.startCameraState=this.renderer.getCamera().getState(),this.startTouchesPositions=s.map(function(v){return Qt(v,r.container)}),this.touchMode===2){var a=Bn(this.startTouchesPositions,2),o=a[0],l=o.x,h=o.y,d=a[1],m=d.x,f=d.y;this.startTouchesAngle=Math.atan2(f-h,m-l),this.startTouchesDistance=Math.sqrt(Math.pow(m-l,2)+Math.pow(f-h,2))}this.emit("touchdown",vr(n,this.lastTouches,this.container)),this.lastTouches=s,this.lastTouchesPositions=this.startTouchesPositions}}},{key:"handleLeave",value:function(n){if(!(!this.enabled||!this.startTouchesPositions.length)){switch(n.cancelable&&n.preventDefault(),this.movingTimeout&&(this.isMoving=!1,clearTimeout(this.movingTimeout)),this.touchMode){case 2:if(n.touches.length===1){this.handleStart(n),n.preventDefault();break}case 1:if(this.isMoving){var r=this.renderer.getCamera(),s=r.getState(),a=r.getPreviousState()||{x:0,y:0};r.animate({x:s.x+this.settings.inertiaRatio*(s.x-a.x),y:s.y+this.settings.inertiaRatio*(s.y-a.y)},{duration:this.settings.inertiaDuration,easing:"quadraticOut"})}this.hasMoved=!1,this.isMoving=!1,this.touchMode=0;break}if(this.emit("touchup",vr(n,this.lastTouches,this.container)),!n.touches.length){var o=Qt(this.lastTouches[0],this.container),l=this.startTouchesPositions[0],h=Math.pow(o.x-l.x,2)+Math.pow(o.y-l.y,2);if(!n.touches.length&&h<Math.pow(this.settings.tapMoveTolerance,2))if(this.lastTap&&Date.now()-this.lastTap.time<this.settings.doubleClickTimeout){var d=vr(n,this.lastTouches,this.container);if(this.emit("doubletap",d),this.lastTap=null,!d.sigmaDefaultPrevented){var m=this.renderer.getCamera(),f=m.getBoundedRatio(m.getState().ratio/this.settings.doubleClickZoomingRatio);m.animate(this.renderer.getViewportZoomedState(o,f),{easing:"quadraticInOut",duration:this.settings.doubleClickZoomingDuration})}}else{var v=vr(n,this.lastTouches,this.container);this.emit("tap",v),this.lastTap={time:Date.now(),position:v.touches[0]||v.previousTouches[0]}}}this.lastTouches=Yr(n.touches),this.startTouchesPositions=[]}}},{key:"handleMove",value:function(n){var r=this;if(!(!this.enabled||!this.startTouchesPositions.length)){n.preventDefault();var s=Yr(n.touches),a=s.map(function(Ce){return Qt(Ce,r.container)}),o=this.lastTouches;this.lastTouches=s,this.lastTouchesPositions=a;var l=vr(n,o,this.container);if(this.emit("touchmove",l),!l.sigmaDefaultPrevented&&(this.hasMoved||(this.hasMoved=a.some(function(Ce,ke){var We=r.startTouchesPositions[ke];return We&&(Ce.x!==We.x||Ce.y!==We.y)})),!!this.hasMoved)){this.isMoving=!0,this.movingTimeout&&clearTimeout(this.movingTimeout),this.movingTimeout=window.setTimeout(function(){r.isMoving=!1},this.settings.dragTimeout);var h=this.renderer.getCamera(),d=this.startCameraState,m=this.renderer.getSetting("stagePadding");switch(this.touchMode){case 1:{var f=this.renderer.viewportToFramedGraph((this.startTouchesPositions||[])[0]),v=f.x,S=f.y,E=this.renderer.viewportToFramedGraph(a[0]),_=E.x,g=E.y;h.setState({x:d.x+v-_,y:d.y+S-g});break}case 2:{var I={x:.5,y:.5,angle:0,ratio:1},P=a[0],C=P.x,H=P.y,U=a[1],N=U.x,V=U.y,L=Math.atan2(V-H,N-C)-this.startTouchesAngle,R=Math.hypot(V-H,N-C)/this.startTouchesDistance,F=h.getBoundedRatio(d.ratio/R);I.ratio=F,I.angle=d.angle+L;var Q=this.getDimensions(),Z=this.renderer.viewportToFramedGraph((this.startTouchesPositions||[])[0],{cameraState:d}),J=Math.min(Q.width,Q.height)-2*m,ie=J/Q.width,$=J/Q.height,ue=F/J,j=C-J/2/ie,ge=H-J/2/$,_e=[j*Math.cos(-I.angle)-ge*Math.sin(-I.angle),ge*Math.cos(-I.angle)+j*Math.sin(-I.angle)];j=_e[0],ge=_e[1],I.x=Z.x-j*ue,I.y=Z.y+ge*ue,h.setState(I);break}}}}}},{key:"setSettings",value:function(n){this.settings=n}}])}(Dl);function Nd(i){if(Array.isArray(i))return Ur(i)}function Ud(i){if(typeof Symbol<"u"&&i[Symbol.iterator]!=null||i["@@iterator"]!=null)return Array.from(i)}function Fd(){throw new TypeError(`Invalid attempt to spread non-iterable instance.
In order to be iterable, non-array objects must have a [Symbol.iterator]() method.`)}function Al(i){return Nd(i)||Ud(i)||ra(i)||Fd()}function Od(i,e){if(i==null)return{};var t={};for(var n in i)if({}.hasOwnProperty.call(i,n)){if(e.indexOf(n)!==-1)continue;t[n]=i[n]}return t}function xa(i,e){if(i==null)return{};var t,n,r=Od(i,e);if(Object.getOwnPropertySymbols){var s=Object.getOwnPropertySymbols(i);for(n=0;n<s.length;n++)t=s[n],e.indexOf(t)===-1&&{}.propertyIsEnumerable.call(i,t)&&(r[t]=i[t])}return r}var Cl=function(){function i(e,t){yt(this,i),this.key=e,this.size=t}return xt(i,null,[{key:"compare",value:function(t,n){return t.size>n.size?-1:t.size<n.size||t.key>n.key?1:-1}}])}(),Rl=function(){function i(){yt(this,i),ce(this,"width",0),ce(this,"height",0),ce(this,"cellSize",0),ce(this,"columns",0),ce(this,"rows",0),ce(this,"cells",{})}return xt(i,[{key:"resizeAndClear",value:function(t,n){this.width=t.width,this.height=t.height,this.cellSize=n,this.columns=Math.ceil(t.width/n),this.rows=Math.ceil(t.height/n),this.cells={}}},{key:"getIndex",value:function(t){var n=Math.floor(t.x/this.cellSize),r=Math.floor(t.y/this.cellSize);return r*this.columns+n}},{key:"add",value:function(t,n,r){var s=new Cl(t,n),a=this.getIndex(r),o=this.cells[a];o||(o=[],this.cells[a]=o),o.push(s)}},{key:"organize",value:function(){for(var t in this.cells){var n=this.cells[t];n.sort(Cl.compare)}}},{key:"getLabelsToDisplay",value:function(t,n){var r=this.cellSize*this.cellSize,s=r/t/t,a=s*n/r,o=Math.ceil(a),l=[];for(var h in this.cells)for(var d=this.cells[h],m=0;m<Math.min(o,d.length);m++)l.push(d[m].key);return l}}])}();function kd(i){var e=i.graph,t=i.hoveredNode,n=i.highlightedNodes,r=i.displayedNodeLabels,s=[];return e.forEachEdge(function(a,o,l,h){(l===t||h===t||n.has(l)||n.has(h)||r.has(l)&&r.has(h))&&s.push(a)}),s}var Pl=150,Ll=50,_n=Object.prototype.hasOwnProperty;function Bd(i,e,t){if(!_n.call(t,"x")||!_n.call(t,"y"))throw new Error('Sigma: could not find a valid position (x, y) for node "'.concat(e,'". All your nodes must have a number "x" and "y". Maybe your forgot to apply a layout or your "nodeReducer" is not returning the correct data?'));return t.color||(t.color=i.defaultNodeColor),!t.label&&t.label!==""&&(t.label=null),t.label!==void 0&&t.label!==null?t.label=""+t.label:t.label=null,t.size||(t.size=2),_n.call(t,"hidden")||(t.hidden=!1),_n.call(t,"highlighted")||(t.highlighted=!1),_n.call(t,"forceLabel")||(t.forceLabel=!1),(!t.type||t.type==="")&&(t.type=i.defaultNodeType),t.zIndex||(t.zIndex=0),t}function zd(i,e,t){return t.color||(t.color=i.defaultEdgeColor),t.label||(t.label=""),t.size||(t.size=.5),_n.call(t,"hidden")||(t.hidden=!1),_n.call(t,"forceLabel")||(t.forceLabel=!1),(!t.type||t.type==="")&&(t.type=i.defaultEdgeType),t.zIndex||(t.zIndex=0),t}var Gd=function(i){function e(t,n){var r,s=arguments.length>2&&arguments[2]!==void 0?arguments[2]:{};if(yt(this,e),r=Pt(this,e),ce(r,"elements",{}),ce(r,"canvasContexts",{}),ce(r,"webGLContexts",{}),ce(r,"pickingLayers",new Set),ce(r,"textures",{}),ce(r,"frameBuffers",{}),ce(r,"activeListeners",{}),ce(r,"labelGrid",new Rl),ce(r,"nodeDataCache",{}),ce(r,"edgeDataCache",{}),ce(r,"nodeProgramIndex",{}),ce(r,"edgeProgramIndex",{}),ce(r,"nodesWithForcedLabels",new Set),ce(r,"edgesWithForcedLabels",new Set),ce(r,"nodeExtent",{x:[0,1],y:[0,1]}),ce(r,"nodeZExtent",[1/0,-1/0]),ce(r,"edgeZExtent",[1/0,-1/0]),ce(r,"matrix",Xt()),ce(r,"invMatrix",Xt()),ce(r,"correctionRatio",1),ce(r,"customBBox",null),ce(r,"normalizationFunction",_a({x:[0,1],y:[0,1]})),ce(r,"graphToViewportRatio",1),ce(r,"itemIDsIndex",{}),ce(r,"nodeIndices",{}),ce(r,"edgeIndices",{}),ce(r,"width",0),ce(r,"height",0),ce(r,"pixelRatio",ga()),ce(r,"pickingDownSizingRatio",2*r.pixelRatio),ce(r,"displayedNodeLabels",new Set),ce(r,"displayedEdgeLabels",new Set),ce(r,"highlightedNodes",new Set),ce(r,"hoveredNode",null),ce(r,"hoveredEdge",null),ce(r,"renderFrame",null),ce(r,"renderHighlightedNodesFrame",null),ce(r,"needToProcess",!1),ce(r,"checkEdgesEventsFrame",null),ce(r,"nodePrograms",{}),ce(r,"nodeHoverPrograms",{}),ce(r,"edgePrograms",{}),r.settings=El(s),Xr(r.settings),Ml(t),!(n instanceof HTMLElement))throw new Error("Sigma: container should be an html element.");r.graph=t,r.container=n,r.createWebGLContext("edges",{picking:s.enableEdgeEvents}),r.createCanvasContext("edgeLabels"),r.createWebGLContext("nodes",{picking:!0}),r.createCanvasContext("labels"),r.createCanvasContext("hovers"),r.createWebGLContext("hoverNodes"),r.createCanvasContext("mouse",{style:{touchAction:"none",userSelect:"none"}}),r.resize();for(var a in r.settings.nodeProgramClasses)r.registerNodeProgram(a,r.settings.nodeProgramClasses[a],r.settings.nodeHoverProgramClasses[a]);for(var o in r.settings.edgeProgramClasses)r.registerEdgeProgram(o,r.settings.edgeProgramClasses[o]);return r.camera=new Tl,r.bindCameraHandlers(),r.mouseCaptor=new Pd(r.elements.mouse,r),r.mouseCaptor.setSettings(r.settings),r.touchCaptor=new Dd(r.elements.mouse,r),r.touchCaptor.setSettings(r.settings),r.bindEventHandlers(),r.bindGraphHandlers(),r.handleSettingsUpdate(),r.refresh(),r}return Lt(e,i),xt(e,[{key:"registerNodeProgram",value:function(n,r,s){return this.nodePrograms[n]&&this.nodePrograms[n].kill(),this.nodeHoverPrograms[n]&&this.nodeHoverPrograms[n].kill(),this.nodePrograms[n]=new r(this.webGLContexts.nodes,this.frameBuffers.nodes,this),this.nodeHoverPrograms[n]=new(s||r)(this.webGLContexts.hoverNodes,null,this),this}},{key:"registerEdgeProgram",value:function(n,r){return this.edgePrograms[n]&&this.edgePrograms[n].kill(),this.edgePrograms[n]=new r(this.webGLContexts.edges,this.frameBuffers.edges,this),this}},{key:"unregisterNodeProgram",value:function(n){if(this.nodePrograms[n]){var r=this.nodePrograms,s=r[n],a=xa(r,[n].map(ti));s.kill(),this.nodePrograms=a}if(this.nodeHoverPrograms[n]){var o=this.nodeHoverPrograms,l=o[n],h=xa(o,[n].map(ti));l.kill(),this.nodePrograms=h}return this}},{key:"unregisterEdgeProgram",value:function(n){if(this.edgePrograms[n]){var r=this.edgePrograms,s=r[n],a=xa(r,[n].map(ti));s.kill(),this.edgePrograms=a}return this}},{key:"resetWebGLTexture",value:function(n){var r=this.webGLContexts[n],s=this.frameBuffers[n],a=this.textures[n];a&&r.deleteTexture(a);var o=r.createTexture();return r.bindFramebuffer(r.FRAMEBUFFER,s),r.bindTexture(r.TEXTURE_2D,o),r.texImage2D(r.TEXTURE_2D,0,r.RGBA,this.width,this.height,0,r.RGBA,r.UNSIGNED_BYTE,null),r.framebufferTexture2D(r.FRAMEBUFFER,r.COLOR_ATTACHMENT0,r.TEXTURE_2D,o,0),this.textures[n]=o,this}},{key:"bindCameraHandlers",value:function(){var n=this;return this.activeListeners.camera=function(){n.scheduleRender()},this.camera.on("updated",this.activeListeners.camera),this}},{key:"unbindCameraHandlers",value:function(){return this.camera.removeListener("updated",this.activeListeners.camera),this}},{key:"getNodeAtPosition",value:function(n){var r=n.x,s=n.y,a=oa(this.webGLContexts.nodes,this.frameBuffers.nodes,r,s,this.pixelRatio,this.pickingDownSizingRatio),o=aa.apply(void 0,Al(a)),l=this.itemIDsIndex[o];return l&&l.type==="node"?l.id:null}},{key:"bindEventHandlers",value:function(){var n=this;this.activeListeners.handleResize=function(){n.scheduleRefresh()},window.addEventListener("resize",this.activeListeners.handleResize),this.activeListeners.handleMove=function(s){var a=gr(s),o={event:a,preventSigmaDefault:function(){a.preventSigmaDefault()}},l=n.getNodeAtPosition(a);if(l&&n.hoveredNode!==l&&!n.nodeDataCache[l].hidden){n.hoveredNode&&n.emit("leaveNode",Re(Re({},o),{},{node:n.hoveredNode})),n.hoveredNode=l,n.emit("enterNode",Re(Re({},o),{},{node:l})),n.scheduleHighlightedNodesRender();return}if(n.hoveredNode&&n.getNodeAtPosition(a)!==n.hoveredNode){var h=n.hoveredNode;n.hoveredNode=null,n.emit("leaveNode",Re(Re({},o),{},{node:h})),n.scheduleHighlightedNodesRender();return}if(n.settings.enableEdgeEvents){var d=n.hoveredNode?null:n.getEdgeAtPoint(o.event.x,o.event.y);d!==n.hoveredEdge&&(n.hoveredEdge&&n.emit("leaveEdge",Re(Re({},o),{},{edge:n.hoveredEdge})),d&&n.emit("enterEdge",Re(Re({},o),{},{edge:d})),n.hoveredEdge=d)}},this.activeListeners.handleMoveBody=function(s){var a=gr(s);n.emit("moveBody",{event:a,preventSigmaDefault:function(){a.preventSigmaDefault()}})},this.activeListeners.handleLeave=function(s){var a=gr(s),o={event:a,preventSigmaDefault:function(){a.preventSigmaDefault()}};n.hoveredNode&&(n.emit("leaveNode",Re(Re({},o),{},{node:n.hoveredNode})),n.scheduleHighlightedNodesRender()),n.settings.enableEdgeEvents&&n.hoveredEdge&&(n.emit("leaveEdge",Re(Re({},o),{},{edge:n.hoveredEdge})),n.scheduleHighlightedNodesRender()),n.emit("leaveStage",Re({},o))},this.activeListeners.handleEnter=function(s){var a=gr(s),o={event:a,preventSigmaDefault:function(){a.preventSigmaDefault()}};n.emit("enterStage",Re({},o))};var r=function(a){return function(o){var l=gr(o),h={event:l,preventSigmaDefault:function(){l.preventSigmaDefault()}},d=n.getNodeAtPosition(l);if(d)return n.emit("".concat(a,"Node"),Re(Re({},h),{},{node:d}));if(n.settings.enableEdgeEvents){var m=n.getEdgeAtPoint(l.x,l.y);if(m)return n.emit("".concat(a,"Edge"),Re(Re({},h),{},{edge:m}))}return n.emit("".concat(a,"Stage"),h)}};return this.activeListeners.handleClick=r("click"),this.activeListeners.handleRightClick=r("rightClick"),this.activeListeners.handleDoubleClick=r("doubleClick"),this.activeListeners.handleWheel=r("wheel"),this.activeListeners.handleDown=r("down"),this.activeListeners.handleUp=r("up"),this.mouseCaptor.on("mousemove",this.activeListeners.handleMove),this.mouseCaptor.on("mousemovebody",this.activeListeners.handleMoveBody),this.mouseCaptor.on("click",this.activeListeners.handleClick),this.mouseCaptor.on("rightClick",this.activeListeners.handleRightClick),this.mouseCaptor.on("doubleClick",this.activeListeners.handleDoubleClick),this.mouseCaptor.on("wheel",this.activeListeners.handleWheel),this.mouseCaptor.on("mousedown",this.activeListeners.handleDown),this.mouseCaptor.on("mouseup",this.activeListeners.handleUp),this.mouseCaptor.on("mouseleave",this.activeListeners.handleLeave),this.mouseCaptor.on("mouseenter",this.activeListeners.handleEnter),this.touchCaptor.on("touchdown",this.activeListeners.handleDown),this.touchCaptor.on("touchdown",this.activeListeners.handleMove),this.touchCaptor.on("touchup",this.activeListeners.handleUp),this.touchCaptor.on("touchmove",this.activeListeners.handleMove),this.touchCaptor.on("tap",this.activeListeners.handleClick),this.touchCaptor.on("doubletap",this.activeListeners.handleDoubleClick),this.touchCaptor.on("touchmove",this.activeListeners.handleMoveBody),this}},{key:"bindGraphHandlers",value:function(){var n=this,r=this.graph,s=new Set(["x","y","zIndex","type"]);return this.activeListeners.eachNodeAttributesUpdatedGraphUpdate=function(a){var o,l=(o=a.hints)===null||o===void 0?void 0:o.attributes;n.graph.forEachNode(function(d){return n.updateNode(d)});var h=!l||l.some(function(d){return s.has(d)});n.refresh({partialGraph:{nodes:r.nodes()},skipIndexation:!h,schedule:!0})},this.activeListeners.eachEdgeAttributesUpdatedGraphUpdate=function(a){var o,l=(o=a.hints)===null||o===void 0?void 0:o.attributes;n.graph.forEachEdge(function(d){return n.updateEdge(d)});var h=l&&["zIndex","type"].some(function(d){return l?.includes(d)});n.refresh({partialGraph:{edges:r.edges()},skipIndexation:!h,schedule:!0})},this.activeListeners.addNodeGraphUpdate=function(a){var o=a.key;n.addNode(o),n.refresh({partialGraph:{nodes:[o]},skipIndexation:!1,schedule:!0})},this.activeListeners.updateNodeGraphUpdate=function(a){var o=a.key;n.refresh({partialGraph:{nodes:[o]},skipIndexation:!1,schedule:!0})},this.activeListeners.dropNodeGraphUpdate=function(a){var o=a.key;n.removeNode(o),n.refresh({schedule:!0})},this.activeListeners.addEdgeGraphUpdate=function(a){var o=a.key;n.addEdge(o),n.refresh({partialGraph:{edges:[o]},schedule:!0})},this.activeListeners.updateEdgeGraphUpdate=function(a){var o=a.key;n.refresh({partialGraph:{edges:[o]},skipIndexation:!1,schedule:!0})},this.activeListeners.dropEdgeGraphUpdate=function(a){var o=a.key;n.removeEdge(o),n.refresh({schedule:!0})},this.activeListeners.clearEdgesGraphUpdate=function(){n.clearEdgeState(),n.clearEdgeIndices(),n.refresh({schedule:!0})},this.activeListeners.clearGraphUpdate=function(){n.clearEdgeState(),n.clearNodeState(),n.clearEdgeIndices(),n.clearNodeIndices(),n.refresh({schedule:!0})},r.on("nodeAdded",this.activeListeners.addNodeGraphUpdate),r.on("nodeDropped",this.activeListeners.dropNodeGraphUpdate),r.on("nodeAttributesUpdated",this.activeListeners.updateNodeGraphUpdate),r.on("eachNodeAttributesUpdated",this.activeListeners.eachNodeAttributesUpdatedGraphUpdate),r.on("edgeAdded",this.activeListeners.addEdgeGraphUpdate),r.on("edgeDropped",this.activeListeners.dropEdgeGraphUpdate),r.on("edgeAttributesUpdated",this.activeListeners.updateEdgeGraphUpdate),r.on("eachEdgeAttributesUpdated",this.activeListeners.eachEdgeAttributesUpdatedGraphUpdate),r.on("edgesCleared",this.activeListeners.clearEdgesGraphUpdate),r.on("cleared",this.activeListeners.clearGraphUpdate),this}},{key:"unbindGraphHandlers",value:function(){var n=this.graph;n.removeListener("nodeAdded",this.activeListeners.addNodeGraphUpdate),n.removeListener("nodeDropped",this.activeListeners.dropNodeGraphUpdate),n.removeListener("nodeAttributesUpdated",this.activeListeners.updateNodeGraphUpdate),n.removeListener("eachNodeAttributesUpdated",this.activeListeners.eachNodeAttributesUpdatedGraphUpdate),n.removeListener("edgeAdded",this.activeListeners.addEdgeGraphUpdate),n.removeListener("edgeDropped",this.activeListeners.dropEdgeGraphUpdate),n.removeListener("edgeAttributesUpdated",this.activeListeners.updateEdgeGraphUpdate),n.removeListener("eachEdgeAttributesUpdated",this.activeListeners.eachEdgeAttributesUpdatedGraphUpdate),n.removeListener("edgesCleared",this.activeListeners.clearEdgesGraphUpdate),n.removeListener("cleared",this.activeListeners.clearGraphUpdate)}},{key:"getEdgeAtPoint",value:function(n,r){var s=oa(this.webGLContexts.edges,this.frameBuffers.edges,n,r,this.pixelRatio,this.pickingDownSizingRatio),a=aa.apply(void 0,Al(s)),o=this.itemIDsIndex[a];return o&&o.type==="edge"?o.id:null}},{key:"process",value:function(){var n=this;this.emit("beforeProcess");var r=this.graph,s=this.settings,a=this.getDimensions();if(this.nodeExtent=Sl(this.graph),!this.settings.autoRescale){var o=a.width,l=a.height,h=this.nodeExtent,d=h.x,m=h.y;this.nodeExtent={x:[(d[0]+d[1])/2-o/2,(d[0]+d[1])/2+o/2],y:[(m[0]+m[1])/2-l/2,(m[0]+m[1])/2+l/2]}}this.normalizationFunction=_a(this.customBBox||this.nodeExtent);var f=new Tl,v=Ti(f.getState(),a,this.getGraphDimensions(),this.getStagePadding());this.labelGrid.resizeAndClear(a,s.labelGridCellSize);for(var S={},E={},_={},g={},I=1,P=r.nodes(),C=0,H=P.length;C<H;C++){var U=P[C],N=this.nodeDataCache[U],V=r.getNodeAttributes(U);N.x=V.x,N.y=V.y,this.normalizationFunction.applyTo(N),typeof N.label=="string"&&!N.hidden&&this.labelGrid.add(U,N.size,this.framedGraphToViewport(N,{matrix:v})),S[N.type]=(S[N.type]||0)+1}this.labelGrid.organize();for(var L in this.nodePrograms){if(!_n.call(this.nodePrograms,L))throw new Error('Sigma: could not find a suitable program for node type "'.concat(L,'"!'));this.nodePrograms[L].reallocate(S[L]||0),S[L]=0}this.settings.zIndex&&this.nodeZExtent[0]!==this.nodeZExtent[1]&&(P=va(this.nodeZExtent,function(de){return n.nodeDataCache[de].zIndex},P));for(var R=0,F=P.length;R<F;R++){var Q=P[R];E[Q]=I,g[E[Q]]={type:"node",id:Q},I++;var Z=this.nodeDataCache[Q];this.addNodeToProgram(Q,E[Q],S[Z.type]++)}for(var J={},ie=r.edges(),$=0,ue=ie.length;$<ue;$++){var j=ie[$],ge=this.edgeDataCache[j];J[ge.type]=(J[ge.type]||0)+1}this.settings.zIndex&&this.edgeZExtent[0]!==this.edgeZExtent[1]&&(ie=va(this.edgeZExtent,function(de){return n.edgeDataCache[de].zIndex},ie));for(var _e in this.edgePrograms){if(!_n.call(this.edgePrograms,_e))throw new Error('Sigma: could not find a suitable program for edge type "'.concat(_e,'"!'));this.edgePrograms[_e].reallocate(J[_e]||0),J[_e]=0}for(var Ce=0,ke=ie.length;Ce<ke;Ce++){var We=ie[Ce];_[We]=I,g[_[We]]={type:"edge",id:We},I++;var re=this.edgeDataCache[We];this.addEdgeToProgram(We,_[We],J[re.type]++)}return this.itemIDsIndex=g,this.nodeIndices=E,this.edgeIndices=_,this.emit("afterProcess"),this}},{key:"handleSettingsUpdate",value:function(n){var r=this,s=this.settings;if(this.camera.minRatio=s.minCameraRatio,this.camera.maxRatio=s.maxCameraRatio,this.camera.enabledZooming=s.enableCameraZooming,this.camera.enabledPanning=s.enableCameraPanning,this.camera.enabledRotation=s.enableCameraRotation,s.cameraPanBoundaries?this.camera.clean=function(d){return r.cleanCameraState(d,s.cameraPanBoundaries&&Vr(s.cameraPanBoundaries)==="object"?s.cameraPanBoundaries:{})}:this.camera.clean=null,this.camera.setState(this.camera.validateState(this.camera.getState())),n){if(n.edgeProgramClasses!==s.edgeProgramClasses){for(var a in s.edgeProgramClasses)s.edgeProgramClasses[a]!==n.edgeProgramClasses[a]&&this.registerEdgeProgram(a,s.edgeProgramClasses[a]);for(var o in n.edgeProgramClasses)s.edgeProgramClasses[o]||this.unregisterEdgeProgram(o)}if(n.nodeProgramClasses!==s.nodeProgramClasses||n.nodeHoverProgramClasses!==s.nodeHoverProgramClasses){for(var l in s.nodeProgramClasses)(s.nodeProgramClasses[l]!==n.nodeProgramClasses[l]||s.nodeHoverProgramClasses[l]!==n.nodeHoverProgramClasses[l])&&this.registerNodeProgram(l,s.nodeProgramClasses[l],s.nodeHoverProgramClasses[l]);for(var h in n.nodeProgramClasses)s.nodeProgramClasses[h]||this.unregisterNodeProgram(h)}}return this.mouseCaptor.setSettings(this.settings),this.touchCaptor.setSettings(this.settings),this}},{key:"cleanCameraState",value:function(n){var r=arguments.length>1&&arguments[1]!==void 0?arguments[1]:{},s=r.tolerance,a=s===void 0?0:s,o=r.boundaries,l=Re({},n),h=o||this.nodeExtent,d=Bn(h.x,2),m=d[0],f=d[1],v=Bn(h.y,2),S=v[0],E=v[1],_=[this.graphToViewport({x:m,y:S},{cameraState:n}),this.graphToViewport({x:f,y:S},{cameraState:n}),this.graphToViewport({x:m,y:E},{cameraState:n}),this.graphToViewport({x:f,y:E},{cameraState:n})],g=1/0,I=-1/0,P=1/0,C=-1/0;_.forEach(function(J){var ie=J.x,$=J.y;g=Math.min(g,ie),I=Math.max(I,ie),P=Math.min(P,$),C=Math.max(C,$)});var H=I-g,U=C-P,N=this.getDimensions(),V=N.width,L=N.height,R=0,F=0;if(H>=V?I<V-a?R=I-(V-a):g>a&&(R=g-a):I>V+a?R=I-(V+a):g<-a&&(R=g+a),U>=L?C<L-a?F=C-(L-a):P>a&&(F=P-a):C>L+a?F=C-(L+a):P<-a&&(F=P+a),R||F){var Q=this.viewportToFramedGraph({x:0,y:0},{cameraState:n}),Z=this.viewportToFramedGraph({x:R,y:F},{cameraState:n});R=Z.x-Q.x,F=Z.y-Q.y,l.x+=R,l.y+=F}return l}},{key:"renderLabels",value:function(){if(!this.settings.renderLabels)return this;var n=this.camera.getState(),r=this.labelGrid.getLabelsToDisplay(n.ratio,this.settings.labelDensity);ya(r,this.nodesWithForcedLabels),this.displayedNodeLabels=new Set;for(var s=this.canvasContexts.labels,a=0,o=r.length;a<o;a++){var l=r[a],h=this.nodeDataCache[l];if(!this.displayedNodeLabels.has(l)&&!h.hidden){var d=this.framedGraphToViewport(h),m=d.x,f=d.y,v=this.scaleSize(h.size);if(!(!h.forceLabel&&v<this.settings.labelRenderedSizeThreshold)&&!(m<-Pl||m>this.width+Pl||f<-Ll||f>this.height+Ll)){this.displayedNodeLabels.add(l);var S=this.settings.defaultDrawNodeLabel,E=this.nodePrograms[h.type],_=E?.drawLabel||S;_(s,Re(Re({key:l},h),{},{size:v,x:m,y:f}),this.settings)}}}return this}},{key:"renderEdgeLabels",value:function(){if(!this.settings.renderEdgeLabels)return this;var n=this.canvasContexts.edgeLabels;n.clearRect(0,0,this.width,this.height);var r=kd({graph:this.graph,hoveredNode:this.hoveredNode,displayedNodeLabels:this.displayedNodeLabels,highlightedNodes:this.highlightedNodes});ya(r,this.edgesWithForcedLabels);for(var s=new Set,a=0,o=r.length;a<o;a++){var l=r[a],h=this.graph.extremities(l),d=this.nodeDataCache[h[0]],m=this.nodeDataCache[h[1]],f=this.edgeDataCache[l];if(!s.has(l)&&!(f.hidden||d.hidden||m.hidden)){var v=this.settings.defaultDrawEdgeLabel,S=this.edgePrograms[f.type],E=S?.drawLabel||v;E(n,Re(Re({key:l},f),{},{size:this.scaleSize(f.size)}),Re(Re(Re({key:h[0]},d),this.framedGraphToViewport(d)),{},{size:this.scaleSize(d.size)}),Re(Re(Re({key:h[1]},m),this.framedGraphToViewport(m)),{},{size:this.scaleSize(m.size)}),this.settings),s.add(l)}}return this.displayedEdgeLabels=s,this}},{key:"renderHighlightedNodes",value:function(){var n=this,r=this.canvasContexts.hovers;r.clearRect(0,0,this.width,this.height);var s=function(v){var S=n.nodeDataCache[v],E=n.framedGraphToViewport(S),_=E.x,g=E.y,I=n.scaleSize(S.size),P=n.settings.defaultDrawNodeHover,C=n.nodePrograms[S.type],H=C?.drawHover||P;H(r,Re(Re({key:v},S),{},{size:I,x:_,y:g}),n.settings)},a=[];this.hoveredNode&&!this.nodeDataCache[this.hoveredNode].hidden&&a.push(this.hoveredNode),this.highlightedNodes.forEach(function(f){f!==n.hoveredNode&&a.push(f)}),a.forEach(function(f){return s(f)});var o={};a.forEach(function(f){var v=n.nodeDataCache[f].type;o[v]=(o[v]||0)+1});for(var l in this.nodeHoverPrograms)this.nodeHoverPrograms[l].reallocate(o[l]||0),o[l]=0;a.forEach(function(f){var v=n.nodeDataCache[f];n.nodeHoverPrograms[v.type].process(0,o[v.type]++,v)}),this.webGLContexts.hoverNodes.clear(this.webGLContexts.hoverNodes.COLOR_BUFFER_BIT);var h=this.getRenderParams();for(var d in this.nodeHoverPrograms){var m=this.nodeHoverPrograms[d];m.render(h)}}},{key:"scheduleHighlightedNodesRender",value:function(){var n=this;this.renderHighlightedNodesFrame||this.renderFrame||(this.renderHighlightedNodesFrame=requestAnimationFrame(function(){n.renderHighlightedNodesFrame=null,n.renderHighlightedNodes(),n.renderEdgeLabels()}))}},{key:"render",value:function(){var n=this;this.emit("beforeRender");var r=function(){return n.emit("afterRender"),n};if(this.renderFrame&&(cancelAnimationFrame(this.renderFrame),this.renderFrame=null),this.resize(),this.needToProcess&&this.process(),this.needToProcess=!1,this.clear(),this.pickingLayers.forEach(function(_){return n.resetWebGLTexture(_)}),!this.graph.order)return r();var s=this.mouseCaptor,a=this.camera.isAnimated()||s.isMoving||s.draggedEvents||s.currentWheelDirection,o=this.camera.getState(),l=this.getDimensions(),h=this.getGraphDimensions(),d=this.getStagePadding();this.matrix=Ti(o,l,h,d),this.invMatrix=Ti(o,l,h,d,!0),this.correctionRatio=bl(this.matrix,o,l),this.graphToViewportRatio=this.getGraphToViewportRatio();var m=this.getRenderParams();for(var f in this.nodePrograms){var v=this.nodePrograms[f];v.render(m)}if(!this.settings.hideEdgesOnMove||!a)for(var S in this.edgePrograms){var E=this.edgePrograms[S];E.render(m)}return this.settings.hideLabelsOnMove&&a||(this.renderLabels(),this.renderEdgeLabels(),this.renderHighlightedNodes()),r()}},{key:"addNode",value:function(n){var r=Object.assign({},this.graph.getNodeAttributes(n));this.settings.nodeReducer&&(r=this.settings.nodeReducer(n,r));var s=Bd(this.settings,n,r);this.nodeDataCache[n]=s,this.nodesWithForcedLabels.delete(n),s.forceLabel&&!s.hidden&&this.nodesWithForcedLabels.add(n),this.highlightedNodes.delete(n),s.highlighted&&!s.hidden&&this.highlightedNodes.add(n),this.settings.zIndex&&(s.zIndex<this.nodeZExtent[0]&&(this.nodeZExtent[0]=s.zIndex),s.zIndex>this.nodeZExtent[1]&&(this.nodeZExtent[1]=s.zIndex))}},{key:"updateNode",value:function(n){this.addNode(n);var r=this.nodeDataCache[n];this.normalizationFunction.applyTo(r)}},{key:"removeNode",value:function(n){delete this.nodeDataCache[n],delete this.nodeProgramIndex[n],this.highlightedNodes.delete(n),this.hoveredNode===n&&(this.hoveredNode=null),this.nodesWithForcedLabels.delete(n)}},{key:"addEdge",value:function(n){var r=Object.assign({},this.graph.getEdgeAttributes(n));this.settings.edgeReducer&&(r=this.settings.edgeReducer(n,r));var s=zd(this.settings,n,r);this.edgeDataCache[n]=s,this.edgesWithForcedLabels.delete(n),s.forceLabel&&!s.hidden&&this.edgesWithForcedLabels.add(n),this.settings.zIndex&&(s.zIndex<this.edgeZExtent[0]&&(this.edgeZExtent[0]=s.zIndex),s.zIndex>this.edgeZExtent[1]&&(this.edgeZExtent[1]=s.zIndex))}},{key:"updateEdge",value:function(n){this.addEdge(n)}},{key:"removeEdge",value:function(n){delete this.edgeDataCache[n],delete this.edgeProgramIndex[n],this.hoveredEdge===n&&(this.hoveredEdge=null),this.edgesWithForcedLabels.delete(n)}},{key:"clearNodeIndices",value:function(){this.labelGrid=new Rl,this.nodeExtent={x:[0,1],y:[0,1]},this.nodeDataCache={},this.edgeProgramIndex={},this.nodesWithForcedLabels=new Set,this.nodeZExtent=[1/0,-1/0],this.highlightedNodes=new Set}},{key:"clearEdgeIndices",value:function(){this.edgeDataCache={},this.edgeProgramIndex={},this.edgesWithForcedLabels=new Set,this.edgeZExtent=[1/0,-1/0]}},{key:"clearIndices",value:function(){this.clearEdgeIndices(),this.clearNodeIndices()}},{key:"clearNodeState",value:function(){this.displayedNodeLabels=new Set,this.highlightedNodes=new Set,this.hoveredNode=null}},{key:"clearEdgeState",value:function(){this.displayedEdgeLabels=new Set,this.highlightedNodes=new Set,this.hoveredEdge=null}},{key:"clearState",value:function(){this.clearEdgeState(),this.clearNodeState()}},{key:"addNodeToProgram",value:function(n,r,s){var a=this.nodeDataCache[n],o=this.nodePrograms[a.type];if(!o)throw new Error('Sigma: could not find a suitable program for node type "'.concat(a.type,'"!'));o.process(r,s,a),this.nodeProgramIndex[n]=s}},{key:"addEdgeToProgram",value:function(n,r,s){var a=this.edgeDataCache[n],o=this.edgePrograms[a.type];if(!o)throw new Error('Sigma: could not find a suitable program for edge type "'.concat(a.type,'"!'));var l=this.graph.extremities(n),h=this.nodeDataCache[l[0]],d=this.nodeDataCache[l[1]];o.process(r,s,h,d,a),this.edgeProgramIndex[n]=s}},{key:"getRenderParams",value:function(){return{matrix:this.matrix,invMatrix:this.invMatrix,width:this.width,height:this.height,pixelRatio:this.pixelRatio,zoomRatio:this.camera.ratio,cameraAngle:this.camera.angle,sizeRatio:1/this.scaleSize(),correctionRatio:this.correctionRatio,downSizingRatio:this.pickingDownSizingRatio,minEdgeThickness:this.settings.minEdgeThickness,antiAliasingFeather:this.settings.antiAliasingFeather}}},{key:"getStagePadding",value:function(){var n=this.settings,r=n.stagePadding,s=n.autoRescale;return s&&r||0}},{key:"createLayer",value:function(n,r){var s=arguments.length>2&&arguments[2]!==void 0?arguments[2]:{};if(this.elements[n])throw new Error('Sigma: a layer named "'.concat(n,'" already exists'));var a=wl(r,{position:"absolute"},{class:"sigma-".concat(n)});return s.style&&Object.assign(a.style,s.style),this.elements[n]=a,"beforeLayer"in s&&s.beforeLayer?this.elements[s.beforeLayer].before(a):"afterLayer"in s&&s.afterLayer?this.elements[s.afterLayer].after(a):this.container.appendChild(a),a}},{key:"createCanvas",value:function(n){var r=arguments.length>1&&arguments[1]!==void 0?arguments[1]:{};return this.createLayer(n,"canvas",r)}},{key:"createCanvasContext",value:function(n){var r=arguments.length>1&&arguments[1]!==void 0?arguments[1]:{},s=this.createCanvas(n,r),a={preserveDrawingBuffer:!1,antialias:!1};return this.canvasContexts[n]=s.getContext("2d",a),this}},{key:"createWebGLContext",value:function(n){var r=arguments.length>1&&arguments[1]!==void 0?arguments[1]:{},s=r?.canvas||this.createCanvas(n,r);r.hidden&&s.remove();var a=Re({preserveDrawingBuffer:!1,antialias:!1},r),o;o=s.getContext("webgl2",a),o||(o=s.getContext("webgl",a)),o||(o=s.getContext("experimental-webgl",a));var l=o;if(this.webGLContexts[n]=l,l.blendFunc(l.ONE,l.ONE_MINUS_SRC_ALPHA),r.picking){this.pickingLayers.add(n);var h=l.createFramebuffer();if(!h)throw new Error("Sigma: cannot create a new frame buffer for layer ".concat(n));this.frameBuffers[n]=h}return l}},{key:"killLayer",value:function(n){var r=this.elements[n];if(!r)throw new Error("Sigma: cannot kill layer ".concat(n,", which does not exist"));if(this.webGLContexts[n]){var s,a=this.webGLContexts[n];(s=a.getExtension("WEBGL_lose_context"))===null||s===void 0||s.loseContext(),delete this.webGLContexts[n]}else this.canvasContexts[n]&&delete this.canvasContexts[n];return r.remove(),delete this.elements[n],this}},{key:"getCamera",value:function(){return this.camera}},{key:"setCamera",value:function(n){this.unbindCameraHandlers(),this.camera=n,this.bindCameraHandlers()}},{key:"getContainer",value:function(){return this.container}},{key:"getGraph",value:function(){return this.graph}},{key:"setGraph",value:function(n){n!==this.graph&&(this.hoveredNode&&!n.hasNode(this.hoveredNode)&&(this.hoveredNode=null),this.hoveredEdge&&!n.hasEdge(this.hoveredEdge)&&(this.hoveredEdge=null),this.unbindGraphHandlers(),this.checkEdgesEventsFrame!==null&&(cancelAnimationFrame(this.checkEdgesEventsFrame),this.checkEdgesEventsFrame=null),this.graph=n,this.bindGraphHandlers(),this.refresh())}},{key:"getMouseCaptor",value:function(){return this.mouseCaptor}},{key:"getTouchCaptor",value:function(){return this.touchCaptor}},{key:"getDimensions",value:function(){return{width:this.width,height:this.height}}},{key:"getGraphDimensions",value:function(){var n=this.customBBox||this.nodeExtent;return{width:n.x[1]-n.x[0]||1,height:n.y[1]-n.y[0]||1}}},{key:"getNodeDisplayData",value:function(n){var r=this.nodeDataCache[n];return r?Object.assign({},r):void 0}},{key:"getEdgeDisplayData",value:function(n){var r=this.edgeDataCache[n];return r?Object.assign({},r):void 0}},{key:"getNodeDisplayedLabels",value:function(){return new Set(this.displayedNodeLabels)}},{key:"getEdgeDisplayedLabels",value:function(){return new Set(this.displayedEdgeLabels)}},{key:"getSettings",value:function(){return Re({},this.settings)}},{key:"getSetting",value:function(n){return this.settings[n]}},{key:"setSetting",value:function(n,r){var s=Re({},this.settings);return this.settings[n]=r,Xr(this.settings),this.handleSettingsUpdate(s),this.scheduleRefresh(),this}},{key:"updateSetting",value:function(n,r){return this.setSetting(n,r(this.settings[n])),this}},{key:"setSettings",value:function(n){var r=Re({},this.settings);return this.settings=Re(Re({},this.settings),n),Xr(this.settings),this.handleSettingsUpdate(r),this.scheduleRefresh(),this}},{key:"resize",value:function(n){var r=this.width,s=this.height;if(this.width=this.container.offsetWidth,this.height=this.container.offsetHeight,this.pixelRatio=ga(),this.width===0)if(this.settings.allowInvalidContainer)this.width=1;else throw new Error("Sigma: Container has no width. You can set the allowInvalidContainer setting to true to stop seeing this error.");if(this.height===0)if(this.settings.allowInvalidContainer)this.height=1;else throw new Error("Sigma: Container has no height. You can set the allowInvalidContainer setting to true to stop seeing this error.");if(!n&&r===this.width&&s===this.height)return this;for(var a in this.elements){var o=this.elements[a];o.style.width=this.width+"px",o.style.height=this.height+"px"}for(var l in this.canvasContexts)this.elements[l].setAttribute("width",this.width*this.pixelRatio+"px"),this.elements[l].setAttribute("height",this.height*this.pixelRatio+"px"),this.pixelRatio!==1&&this.canvasContexts[l].scale(this.pixelRatio,this.pixelRatio);for(var h in this.webGLContexts){this.elements[h].setAttribute("width",this.width*this.pixelRatio+"px"),this.elements[h].setAttribute("height",this.height*this.pixelRatio+"px");var d=this.webGLContexts[h];if(d.viewport(0,0,this.width*this.pixelRatio,this.height*this.pixelRatio),this.pickingLayers.has(h)){var m=this.textures[h];m&&d.deleteTexture(m)}}return this.emit("resize"),this}},{key:"clear",value:function(){return this.emit("beforeClear"),this.webGLContexts.nodes.bindFramebuffer(WebGLRenderingContext.FRAMEBUFFER,null),this.webGLContexts.nodes.clear(WebGLRenderingContext.COLOR_BUFFER_BIT),this.webGLContexts.edges.bindFramebuffer(WebGLRenderingContext.FRAMEBUFFER,null),this.webGLContexts.edges.clear(WebGLRenderingContext.COLOR_BUFFER_BIT),this.webGLContexts.hoverNodes.clear(WebGLRenderingContext.COLOR_BUFFER_BIT),this.canvasContexts.labels.clearRect(0,0,this.width,this.height),this.canvasContexts.hovers.clearRect(0,0,this.width,this.height),this.canvasContexts.edgeLabels.clearRect(0,0,this.width,this.height),this.emit("afterClear"),this}},{key:"refresh",value:function(n){var r=this,s=n?.skipIndexation!==void 0?n?.skipIndexation:!1,a=n?.schedule!==void 0?n.schedule:!1,o=!n||!n.partialGraph;if(o)this.clearEdgeIndices(),this.clearNodeIndices(),this.graph.forEachNode(function(C){return r.addNode(C)}),this.graph.forEachEdge(function(C){return r.addEdge(C)});else{for(var l,h,d=((l=n.partialGraph)===null||l===void 0?void 0:l.nodes)||[],m=0,f=d?.length||0;m<f;m++){var v=d[m];if(this.updateNode(v),s){var S=this.nodeProgramIndex[v];if(S===void 0)throw new Error('Sigma: node "'.concat(v,`" can't be repaint`));this.addNodeToProgram(v,this.nodeIndices[v],S)}}for(var E=(n==null||(h=n.partialGraph)===null||h===void 0?void 0:h.edges)||[],_=0,g=E.length;_<g;_++){var I=E[_];if(this.updateEdge(I),s){var P=this.edgeProgramIndex[I];if(P===void 0)throw new Error('Sigma: edge "'.concat(I,`" can't be repaint`));this.addEdgeToProgram(I,this.edgeIndices[I],P)}}}return(o||!s)&&(this.needToProcess=!0),a?this.scheduleRender():this.render(),this}},{key:"scheduleRender",value:function(){var n=this;return this.renderFrame||(this.renderFrame=requestAnimationFrame(function(){n.render()})),this}},{key:"scheduleRefresh",value:function(n){return this.refresh(Re(Re({},n),{},{schedule:!0}))}},{key:"getViewportZoomedState",value:function(n,r){var s=this.camera.getState(),a=s.ratio,o=s.angle,l=s.x,h=s.y,d=this.settings,m=d.minCameraRatio,f=d.maxCameraRatio;typeof f=="number"&&(r=Math.min(r,f)),typeof m=="number"&&(r=Math.max(r,m));var v=r/a,S={x:this.width/2,y:this.height/2},E=this.viewportToFramedGraph(n),_=this.viewportToFramedGraph(S);return{angle:o,x:(E.x-_.x)*(1-v)+l,y:(E.y-_.y)*(1-v)+h,ratio:r}}},{key:"viewRectangle",value:function(){var n=this.viewportToFramedGraph({x:0,y:0}),r=this.viewportToFramedGraph({x:this.width,y:0}),s=this.viewportToFramedGraph({x:0,y:this.height});return{x1:n.x,y1:n.y,x2:r.x,y2:r.y,height:r.y-s.y}}},{key:"framedGraphToViewport",value:function(n){var r=arguments.length>1&&arguments[1]!==void 0?arguments[1]:{},s=!!r.cameraState||!!r.viewportDimensions||!!r.graphDimensions,a=r.matrix?r.matrix:s?Ti(r.cameraState||this.camera.getState(),r.viewportDimensions||this.getDimensions(),r.graphDimensions||this.getGraphDimensions(),r.padding||this.getStagePadding()):this.matrix,o=Gr(a,n);return{x:(1+o.x)*this.width/2,y:(1-o.y)*this.height/2}}},{key:"viewportToFramedGraph",value:function(n){var r=arguments.length>1&&arguments[1]!==void 0?arguments[1]:{},s=!!r.cameraState||!!r.viewportDimensions||!r.graphDimensions,a=r.matrix?r.matrix:s?Ti(r.cameraState||this.camera.getState(),r.viewportDimensions||this.getDimensions(),r.graphDimensions||this.getGraphDimensions(),r.padding||this.getStagePadding(),!0):this.invMatrix,o=Gr(a,{x:n.x/this.width*2-1,y:1-n.y/this.height*2});return isNaN(o.x)&&(o.x=0),isNaN(o.y)&&(o.y=0),o}},{key:"viewportToGraph",value:function(n){var r=arguments.length>1&&arguments[1]!==void 0?arguments[1]:{};return this.normalizationFunction.inverse(this.viewportToFramedGraph(n,r))}},{key:"graphToViewport",value:function(n){var r=arguments.length>1&&arguments[1]!==void 0?arguments[1]:{};return this.framedGraphToViewport(this.normalizationFunction(n),r)}},{key:"getGraphToViewportRatio",value:function(){var n={x:0,y:0},r={x:1,y:1},s=Math.sqrt(Math.pow(n.x-r.x,2)+Math.pow(n.y-r.y,2)),a=this.graphToViewport(n),o=this.graphToViewport(r),l=Math.sqrt(Math.pow(a.x-o.x,2)+Math.pow(a.y-o.y,2));return l/s}},{key:"getBBox",value:function(){return this.nodeExtent}},{key:"getCustomBBox",value:function(){return this.customBBox}},{key:"setCustomBBox",value:function(n){return this.customBBox=n,this.scheduleRender(),this}},{key:"kill",value:function(){this.emit("kill"),this.removeAllListeners(),this.unbindCameraHandlers(),window.removeEventListener("resize",this.activeListeners.handleResize),this.mouseCaptor.kill(),this.touchCaptor.kill(),this.unbindGraphHandlers(),this.clearIndices(),this.clearState(),this.nodeDataCache={},this.edgeDataCache={},this.highlightedNodes.clear(),this.renderFrame&&(cancelAnimationFrame(this.renderFrame),this.renderFrame=null),this.renderHighlightedNodesFrame&&(cancelAnimationFrame(this.renderHighlightedNodesFrame),this.renderHighlightedNodesFrame=null);for(var n=this.container;n.firstChild;)n.removeChild(n.firstChild);for(var r in this.nodePrograms)this.nodePrograms[r].kill();for(var s in this.nodeHoverPrograms)this.nodeHoverPrograms[s].kill();for(var a in this.edgePrograms)this.edgePrograms[a].kill();this.nodePrograms={},this.nodeHoverPrograms={},this.edgePrograms={};for(var o in this.elements)this.killLayer(o);this.canvasContexts={},this.webGLContexts={},this.elements={}}},{key:"scaleSize",value:function(){var n=arguments.length>0&&arguments[0]!==void 0?arguments[0]:1,r=arguments.length>1&&arguments[1]!==void 0?arguments[1]:this.camera.ratio;return n/this.settings.zoomToSizeRatioFunction(r)*(this.getSetting("itemSizesReference")==="positions"?r*this.graphToViewportRatio:1)}},{key:"getCanvases",value:function(){var n={};for(var r in this.elements)this.elements[r]instanceof HTMLCanvasElement&&(n[r]=this.elements[r]);return n}}])}(Br),Nl=Gd;var hc="170",yi={LEFT:0,MIDDLE:1,RIGHT:2,ROTATE:0,DOLLY:1,PAN:2},xi={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},Vd=0,Ul=1,Hd=2;var kh=1,Wd=2,wn=3,Kn=0,kt=1,En=2,Zn=0,Wi=1,Fl=2,Ol=3,kl=4,Xd=5,hi=100,qd=101,Yd=102,Zd=103,$d=104,Kd=200,jd=201,Jd=202,Qd=203,$a=204,Ka=205,ef=206,tf=207,nf=208,rf=209,sf=210,af=211,of=212,cf=213,lf=214,ja=0,Ja=1,Qa=2,Zi=3,eo=4,to=5,no=6,io=7,Bh=0,hf=1,uf=2,$n=0,df=1,ff=2,pf=3,mf=4,gf=5,vf=6,_f=7;var zh=300,$i=301,Ki=302,ro=303,so=304,Hs=306,ao=1e3,fi=1001,oo=1002,on=1003,yf=1004;var Zr=1005;var fn=1006,ba=1007;var pi=1008;var Rn=1009,Gh=1010,Vh=1011,Ar=1012,uc=1013,mi=1014,Tn=1015,Ir=1016,dc=1017,fc=1018,ji=1020,Hh=35902,Wh=1021,Xh=1022,sn=1023,qh=1024,Yh=1025,Xi=1026,Ji=1027,Zh=1028,pc=1029,$h=1030,mc=1031;var gc=1033,_s=33776,ys=33777,xs=33778,bs=33779,co=35840,lo=35841,ho=35842,uo=35843,fo=36196,po=37492,mo=37496,go=37808,vo=37809,_o=37810,yo=37811,xo=37812,bo=37813,So=37814,Mo=37815,wo=37816,Eo=37817,To=37818,Ao=37819,Co=37820,Ro=37821,Ss=36492,Po=36494,Lo=36495,Kh=36283,Io=36284,Do=36285,No=36286;var Ms=2300,Uo=2301,Sa=2302,Bl=2400,zl=2401,Gl=2402;var xf=3200,bf=3201;var Sf=0,Mf=1,Yn="",Yt="srgb",ir="srgb-linear",Ws="linear",ct="srgb";var Ai=7680;var Vl=519,wf=512,Ef=513,Tf=514,jh=515,Af=516,Cf=517,Rf=518,Pf=519,Hl=35044;var Wl="300 es",An=2e3,ws=2001,Pn=class{addEventListener(e,t){this._listeners===void 0&&(this._listeners={});let n=this._listeners;n[e]===void 0&&(n[e]=[]),n[e].indexOf(t)===-1&&n[e].push(t)}hasEventListener(e,t){if(this._listeners===void 0)return!1;let n=this._listeners;return n[e]!==void 0&&n[e].indexOf(t)!==-1}removeEventListener(e,t){if(this._listeners===void 0)return;let r=this._listeners[e];if(r!==void 0){let s=r.indexOf(t);s!==-1&&r.splice(s,1)}}dispatchEvent(e){if(this._listeners===void 0)return;let n=this._listeners[e.type];if(n!==void 0){e.target=this;let r=n.slice(0);for(let s=0,a=r.length;s<a;s++)r[s].call(this,e);e.target=null}}},At=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],Xl=1234567,wr=Math.PI/180,Cr=180/Math.PI;function rr(){let i=Math.random()*4294967295|0,e=Math.random()*4294967295|0,t=Math.random()*4294967295|0,n=Math.random()*4294967295|0;return(At[i&255]+At[i>>8&255]+At[i>>16&255]+At[i>>24&255]+"-"+At[e&255]+At[e>>8&255]+"-"+At[e>>16&15|64]+At[e>>24&255]+"-"+At[t&63|128]+At[t>>8&255]+"-"+At[t>>16&255]+At[t>>24&255]+At[n&255]+At[n>>8&255]+At[n>>16&255]+At[n>>24&255]).toLowerCase()}function Rt(i,e,t){return Math.max(e,Math.min(t,i))}function vc(i,e){return(i%e+e)%e}function Lf(i,e,t,n,r){return n+(i-e)*(r-n)/(t-e)}function If(i,e,t){return i!==e?(t-i)/(e-i):0}function Er(i,e,t){return(1-t)*i+t*e}function Df(i,e,t,n){return Er(i,e,1-Math.exp(-t*n))}function Nf(i,e=1){return e-Math.abs(vc(i,e*2)-e)}function Uf(i,e,t){return i<=e?0:i>=t?1:(i=(i-e)/(t-e),i*i*(3-2*i))}function Ff(i,e,t){return i<=e?0:i>=t?1:(i=(i-e)/(t-e),i*i*i*(i*(i*6-15)+10))}function Of(i,e){return i+Math.floor(Math.random()*(e-i+1))}function kf(i,e){return i+Math.random()*(e-i)}function Bf(i){return i*(.5-Math.random())}function zf(i){i!==void 0&&(Xl=i);let e=Xl+=1831565813;return e=Math.imul(e^e>>>15,e|1),e^=e+Math.imul(e^e>>>7,e|61),((e^e>>>14)>>>0)/4294967296}function Gf(i){return i*wr}function Vf(i){return i*Cr}function Hf(i){return(i&i-1)===0&&i!==0}function Wf(i){return Math.pow(2,Math.ceil(Math.log(i)/Math.LN2))}function Xf(i){return Math.pow(2,Math.floor(Math.log(i)/Math.LN2))}function qf(i,e,t,n,r){let s=Math.cos,a=Math.sin,o=s(t/2),l=a(t/2),h=s((e+n)/2),d=a((e+n)/2),m=s((e-n)/2),f=a((e-n)/2),v=s((n-e)/2),S=a((n-e)/2);switch(r){case"XYX":i.set(o*d,l*m,l*f,o*h);break;case"YZY":i.set(l*f,o*d,l*m,o*h);break;case"ZXZ":i.set(l*m,l*f,o*d,o*h);break;case"XZX":i.set(o*d,l*S,l*v,o*h);break;case"YXY":i.set(l*v,o*d,l*S,o*h);break;case"ZYZ":i.set(l*S,l*v,o*d,o*h);break;default:console.warn("THREE.MathUtils: .setQuaternionFromProperEuler() encountered an unknown order: "+r)}}function Gi(i,e){switch(e.constructor){case Float32Array:return i;case Uint32Array:return i/4294967295;case Uint16Array:return i/65535;case Uint8Array:return i/255;case Int32Array:return Math.max(i/2147483647,-1);case Int16Array:return Math.max(i/32767,-1);case Int8Array:return Math.max(i/127,-1);default:throw new Error("Invalid component type.")}}function It(i,e){switch(e.constructor){case Float32Array:return i;case Uint32Array:return Math.round(i*4294967295);case Uint16Array:return Math.round(i*65535);case Uint8Array:return Math.round(i*255);case Int32Array:return Math.round(i*2147483647);case Int16Array:return Math.round(i*32767);case Int8Array:return Math.round(i*127);default:throw new Error("Invalid component type.")}}var Jh={DEG2RAD:wr,RAD2DEG:Cr,generateUUID:rr,clamp:Rt,euclideanModulo:vc,mapLinear:Lf,inverseLerp:If,lerp:Er,damp:Df,pingpong:Nf,smoothstep:Uf,smootherstep:Ff,randInt:Of,randFloat:kf,randFloatSpread:Bf,seededRandom:zf,degToRad:Gf,radToDeg:Vf,isPowerOfTwo:Hf,ceilPowerOfTwo:Wf,floorPowerOfTwo:Xf,setQuaternionFromProperEuler:qf,normalize:It,denormalize:Gi},$e=class i{constructor(e=0,t=0){i.prototype.isVector2=!0,this.x=e,this.y=t}get width(){return this.x}set width(e){this.x=e}get height(){return this.y}set height(e){this.y=e}set(e,t){return this.x=e,this.y=t,this}setScalar(e){return this.x=e,this.y=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;default:throw new Error("index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;default:throw new Error("index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y)}copy(e){return this.x=e.x,this.y=e.y,this}add(e){return this.x+=e.x,this.y+=e.y,this}addScalar(e){return this.x+=e,this.y+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this}subScalar(e){return this.x-=e,this.y-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this}multiply(e){return this.x*=e.x,this.y*=e.y,this}multiplyScalar(e){return this.x*=e,this.y*=e,this}divide(e){return this.x/=e.x,this.y/=e.y,this}divideScalar(e){return this.multiplyScalar(1/e)}applyMatrix3(e){let t=this.x,n=this.y,r=e.elements;return this.x=r[0]*t+r[3]*n+r[6],this.y=r[1]*t+r[4]*n+r[7],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this}clamp(e,t){return this.x=Math.max(e.x,Math.min(t.x,this.x)),this.y=Math.max(e.y,Math.min(t.y,this.y)),this}clampScalar(e,t){return this.x=Math.max(e,Math.min(t,this.x)),this.y=Math.max(e,Math.min(t,this.y)),this}clampLength(e,t){let n=this.length();return this.divideScalar(n||1).multiplyScalar(Math.max(e,Math.min(t,n)))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(e){return this.x*e.x+this.y*e.y}cross(e){return this.x*e.y-this.y*e.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let n=this.dot(e)/t;return Math.acos(Rt(n,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,n=this.y-e.y;return t*t+n*n}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this}equals(e){return e.x===this.x&&e.y===this.y}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this}rotateAround(e,t){let n=Math.cos(t),r=Math.sin(t),s=this.x-e.x,a=this.y-e.y;return this.x=s*n-a*r+e.x,this.y=s*r+a*n+e.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}},He=class i{constructor(e,t,n,r,s,a,o,l,h){i.prototype.isMatrix3=!0,this.elements=[1,0,0,0,1,0,0,0,1],e!==void 0&&this.set(e,t,n,r,s,a,o,l,h)}set(e,t,n,r,s,a,o,l,h){let d=this.elements;return d[0]=e,d[1]=r,d[2]=o,d[3]=t,d[4]=s,d[5]=l,d[6]=n,d[7]=a,d[8]=h,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(e){let t=this.elements,n=e.elements;return t[0]=n[0],t[1]=n[1],t[2]=n[2],t[3]=n[3],t[4]=n[4],t[5]=n[5],t[6]=n[6],t[7]=n[7],t[8]=n[8],this}extractBasis(e,t,n){return e.setFromMatrix3Column(this,0),t.setFromMatrix3Column(this,1),n.setFromMatrix3Column(this,2),this}setFromMatrix4(e){let t=e.elements;return this.set(t[0],t[4],t[8],t[1],t[5],t[9],t[2],t[6],t[10]),this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let n=e.elements,r=t.elements,s=this.elements,a=n[0],o=n[3],l=n[6],h=n[1],d=n[4],m=n[7],f=n[2],v=n[5],S=n[8],E=r[0],_=r[3],g=r[6],I=r[1],P=r[4],C=r[7],H=r[2],U=r[5],N=r[8];return s[0]=a*E+o*I+l*H,s[3]=a*_+o*P+l*U,s[6]=a*g+o*C+l*N,s[1]=h*E+d*I+m*H,s[4]=h*_+d*P+m*U,s[7]=h*g+d*C+m*N,s[2]=f*E+v*I+S*H,s[5]=f*_+v*P+S*U,s[8]=f*g+v*C+S*N,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[3]*=e,t[6]*=e,t[1]*=e,t[4]*=e,t[7]*=e,t[2]*=e,t[5]*=e,t[8]*=e,this}determinant(){let e=this.elements,t=e[0],n=e[1],r=e[2],s=e[3],a=e[4],o=e[5],l=e[6],h=e[7],d=e[8];return t*a*d-t*o*h-n*s*d+n*o*l+r*s*h-r*a*l}invert(){let e=this.elements,t=e[0],n=e[1],r=e[2],s=e[3],a=e[4],o=e[5],l=e[6],h=e[7],d=e[8],m=d*a-o*h,f=o*l-d*s,v=h*s-a*l,S=t*m+n*f+r*v;if(S===0)return this.set(0,0,0,0,0,0,0,0,0);let E=1/S;return e[0]=m*E,e[1]=(r*h-d*n)*E,e[2]=(o*n-r*a)*E,e[3]=f*E,e[4]=(d*t-r*l)*E,e[5]=(r*s-o*t)*E,e[6]=v*E,e[7]=(n*l-h*t)*E,e[8]=(a*t-n*s)*E,this}transpose(){let e,t=this.elements;return e=t[1],t[1]=t[3],t[3]=e,e=t[2],t[2]=t[6],t[6]=e,e=t[5],t[5]=t[7],t[7]=e,this}getNormalMatrix(e){return this.setFromMatrix4(e).invert().transpose()}transposeIntoArray(e){let t=this.elements;return e[0]=t[0],e[1]=t[3],e[2]=t[6],e[3]=t[1],e[4]=t[4],e[5]=t[7],e[6]=t[2],e[7]=t[5],e[8]=t[8],this}setUvTransform(e,t,n,r,s,a,o){let l=Math.cos(s),h=Math.sin(s);return this.set(n*l,n*h,-n*(l*a+h*o)+a+e,-r*h,r*l,-r*(-h*a+l*o)+o+t,0,0,1),this}scale(e,t){return this.premultiply(Ma.makeScale(e,t)),this}rotate(e){return this.premultiply(Ma.makeRotation(-e)),this}translate(e,t){return this.premultiply(Ma.makeTranslation(e,t)),this}makeTranslation(e,t){return e.isVector2?this.set(1,0,e.x,0,1,e.y,0,0,1):this.set(1,0,e,0,1,t,0,0,1),this}makeRotation(e){let t=Math.cos(e),n=Math.sin(e);return this.set(t,-n,0,n,t,0,0,0,1),this}makeScale(e,t){return this.set(e,0,0,0,t,0,0,0,1),this}equals(e){let t=this.elements,n=e.elements;for(let r=0;r<9;r++)if(t[r]!==n[r])return!1;return!0}fromArray(e,t=0){for(let n=0;n<9;n++)this.elements[n]=e[n+t];return this}toArray(e=[],t=0){let n=this.elements;return e[t]=n[0],e[t+1]=n[1],e[t+2]=n[2],e[t+3]=n[3],e[t+4]=n[4],e[t+5]=n[5],e[t+6]=n[6],e[t+7]=n[7],e[t+8]=n[8],e}clone(){return new this.constructor().fromArray(this.elements)}},Ma=new He;function Qh(i){for(let e=i.length-1;e>=0;--e)if(i[e]>=65535)return!0;return!1}function Es(i){return document.createElementNS("http://www.w3.org/1999/xhtml",i)}function Yf(){let i=Es("canvas");return i.style.display="block",i}var ql={};function Sr(i){i in ql||(ql[i]=!0,console.warn(i))}function Zf(i,e,t){return new Promise(function(n,r){function s(){switch(i.clientWaitSync(e,i.SYNC_FLUSH_COMMANDS_BIT,0)){case i.WAIT_FAILED:r();break;case i.TIMEOUT_EXPIRED:setTimeout(s,t);break;default:n()}}setTimeout(s,t)})}function $f(i){let e=i.elements;e[2]=.5*e[2]+.5*e[3],e[6]=.5*e[6]+.5*e[7],e[10]=.5*e[10]+.5*e[11],e[14]=.5*e[14]+.5*e[15]}function Kf(i){let e=i.elements;e[11]===-1?(e[10]=-e[10]-1,e[14]=-e[14]):(e[10]=-e[10],e[14]=-e[14]+1)}var et={enabled:!0,workingColorSpace:ir,spaces:{},convert:function(i,e,t){return this.enabled===!1||e===t||!e||!t||(this.spaces[e].transfer===ct&&(i.r=Cn(i.r),i.g=Cn(i.g),i.b=Cn(i.b)),this.spaces[e].primaries!==this.spaces[t].primaries&&(i.applyMatrix3(this.spaces[e].toXYZ),i.applyMatrix3(this.spaces[t].fromXYZ)),this.spaces[t].transfer===ct&&(i.r=qi(i.r),i.g=qi(i.g),i.b=qi(i.b))),i},fromWorkingColorSpace:function(i,e){return this.convert(i,this.workingColorSpace,e)},toWorkingColorSpace:function(i,e){return this.convert(i,e,this.workingColorSpace)},getPrimaries:function(i){return this.spaces[i].primaries},getTransfer:function(i){return i===Yn?Ws:this.spaces[i].transfer},getLuminanceCoefficients:function(i,e=this.workingColorSpace){return i.fromArray(this.spaces[e].luminanceCoefficients)},define:function(i){Object.assign(this.spaces,i)},_getMatrix:function(i,e,t){return i.copy(this.spaces[e].toXYZ).multiply(this.spaces[t].fromXYZ)},_getDrawingBufferColorSpace:function(i){return this.spaces[i].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(i=this.workingColorSpace){return this.spaces[i].workingColorSpaceConfig.unpackColorSpace}};function Cn(i){return i<.04045?i*.0773993808:Math.pow(i*.9478672986+.0521327014,2.4)}function qi(i){return i<.0031308?i*12.92:1.055*Math.pow(i,.41666)-.055}var Yl=[.64,.33,.3,.6,.15,.06],Zl=[.2126,.7152,.0722],$l=[.3127,.329],Kl=new He().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),jl=new He().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);et.define({[ir]:{primaries:Yl,whitePoint:$l,transfer:Ws,toXYZ:Kl,fromXYZ:jl,luminanceCoefficients:Zl,workingColorSpaceConfig:{unpackColorSpace:Yt},outputColorSpaceConfig:{drawingBufferColorSpace:Yt}},[Yt]:{primaries:Yl,whitePoint:$l,transfer:ct,toXYZ:Kl,fromXYZ:jl,luminanceCoefficients:Zl,outputColorSpaceConfig:{drawingBufferColorSpace:Yt}}});var Ci,Fo=class{static getDataURL(e){if(/^data:/i.test(e.src)||typeof HTMLCanvasElement>"u")return e.src;let t;if(e instanceof HTMLCanvasElement)t=e;else{Ci===void 0&&(Ci=Es("canvas")),Ci.width=e.width,Ci.height=e.height;let n=Ci.getContext("2d");e instanceof ImageData?n.putImageData(e,0,0):n.drawImage(e,0,0,e.width,e.height),t=Ci}return t.width>2048||t.height>2048?(console.warn("THREE.ImageUtils.getDataURL: Image converted to jpg for performance reasons",e),t.toDataURL("image/jpeg",.6)):t.toDataURL("image/png")}static sRGBToLinear(e){if(typeof HTMLImageElement<"u"&&e instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&e instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&e instanceof ImageBitmap){let t=Es("canvas");t.width=e.width,t.height=e.height;let n=t.getContext("2d");n.drawImage(e,0,0,e.width,e.height);let r=n.getImageData(0,0,e.width,e.height),s=r.data;for(let a=0;a<s.length;a++)s[a]=Cn(s[a]/255)*255;return n.putImageData(r,0,0),t}else if(e.data){let t=e.data.slice(0);for(let n=0;n<t.length;n++)t instanceof Uint8Array||t instanceof Uint8ClampedArray?t[n]=Math.floor(Cn(t[n]/255)*255):t[n]=Cn(t[n]);return{data:t,width:e.width,height:e.height}}else return console.warn("THREE.ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),e}},jf=0,Ts=class{constructor(e=null){this.isSource=!0,Object.defineProperty(this,"id",{value:jf++}),this.uuid=rr(),this.data=e,this.dataReady=!0,this.version=0}set needsUpdate(e){e===!0&&this.version++}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.images[this.uuid]!==void 0)return e.images[this.uuid];let n={uuid:this.uuid,url:""},r=this.data;if(r!==null){let s;if(Array.isArray(r)){s=[];for(let a=0,o=r.length;a<o;a++)r[a].isDataTexture?s.push(wa(r[a].image)):s.push(wa(r[a]))}else s=wa(r);n.url=s}return t||(e.images[this.uuid]=n),n}};function wa(i){return typeof HTMLImageElement<"u"&&i instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&i instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&i instanceof ImageBitmap?Fo.getDataURL(i):i.data?{data:Array.from(i.data),width:i.width,height:i.height,type:i.data.constructor.name}:(console.warn("THREE.Texture: Unable to serialize Texture."),{})}var Jf=0,$t=class i extends Pn{constructor(e=i.DEFAULT_IMAGE,t=i.DEFAULT_MAPPING,n=fi,r=fi,s=fn,a=pi,o=sn,l=Rn,h=i.DEFAULT_ANISOTROPY,d=Yn){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:Jf++}),this.uuid=rr(),this.name="",this.source=new Ts(e),this.mipmaps=[],this.mapping=t,this.channel=0,this.wrapS=n,this.wrapT=r,this.magFilter=s,this.minFilter=a,this.anisotropy=h,this.format=o,this.internalFormat=null,this.type=l,this.offset=new $e(0,0),this.repeat=new $e(1,1),this.center=new $e(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new He,this.generateMipmaps=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=d,this.userData={},this.version=0,this.onUpdate=null,this.isRenderTargetTexture=!1,this.pmremVersion=0}get image(){return this.source.data}set image(e=null){this.source.data=e}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}clone(){return new this.constructor().copy(this)}copy(e){return this.name=e.name,this.source=e.source,this.mipmaps=e.mipmaps.slice(0),this.mapping=e.mapping,this.channel=e.channel,this.wrapS=e.wrapS,this.wrapT=e.wrapT,this.magFilter=e.magFilter,this.minFilter=e.minFilter,this.anisotropy=e.anisotropy,this.format=e.format,this.internalFormat=e.internalFormat,this.type=e.type,this.offset.copy(e.offset),this.repeat.copy(e.repeat),this.center.copy(e.center),this.rotation=e.rotation,this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrix.copy(e.matrix),this.generateMipmaps=e.generateMipmaps,this.premultiplyAlpha=e.premultiplyAlpha,this.flipY=e.flipY,this.unpackAlignment=e.unpackAlignment,this.colorSpace=e.colorSpace,this.userData=JSON.parse(JSON.stringify(e.userData)),this.needsUpdate=!0,this}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.textures[this.uuid]!==void 0)return e.textures[this.uuid];let n={metadata:{version:4.6,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(e).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(n.userData=this.userData),t||(e.textures[this.uuid]=n),n}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(e){if(this.mapping!==zh)return e;if(e.applyMatrix3(this.matrix),e.x<0||e.x>1)switch(this.wrapS){case ao:e.x=e.x-Math.floor(e.x);break;case fi:e.x=e.x<0?0:1;break;case oo:Math.abs(Math.floor(e.x)%2)===1?e.x=Math.ceil(e.x)-e.x:e.x=e.x-Math.floor(e.x);break}if(e.y<0||e.y>1)switch(this.wrapT){case ao:e.y=e.y-Math.floor(e.y);break;case fi:e.y=e.y<0?0:1;break;case oo:Math.abs(Math.floor(e.y)%2)===1?e.y=Math.ceil(e.y)-e.y:e.y=e.y-Math.floor(e.y);break}return this.flipY&&(e.y=1-e.y),e}set needsUpdate(e){e===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(e){e===!0&&this.pmremVersion++}};$t.DEFAULT_IMAGE=null;$t.DEFAULT_MAPPING=zh;$t.DEFAULT_ANISOTROPY=1;var gt=class i{constructor(e=0,t=0,n=0,r=1){i.prototype.isVector4=!0,this.x=e,this.y=t,this.z=n,this.w=r}get width(){return this.z}set width(e){this.z=e}get height(){return this.w}set height(e){this.w=e}set(e,t,n,r){return this.x=e,this.y=t,this.z=n,this.w=r,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this.w=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setW(e){return this.w=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;case 3:this.w=t;break;default:throw new Error("index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this.w=e.w!==void 0?e.w:1,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this.w+=e.w,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this.w+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this.w=e.w+t.w,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this.w+=e.w*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this.w-=e.w,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this.w-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this.w=e.w-t.w,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this.w*=e.w,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this.w*=e,this}applyMatrix4(e){let t=this.x,n=this.y,r=this.z,s=this.w,a=e.elements;return this.x=a[0]*t+a[4]*n+a[8]*r+a[12]*s,this.y=a[1]*t+a[5]*n+a[9]*r+a[13]*s,this.z=a[2]*t+a[6]*n+a[10]*r+a[14]*s,this.w=a[3]*t+a[7]*n+a[11]*r+a[15]*s,this}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this.w/=e.w,this}divideScalar(e){return this.multiplyScalar(1/e)}setAxisAngleFromQuaternion(e){this.w=2*Math.acos(e.w);let t=Math.sqrt(1-e.w*e.w);return t<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=e.x/t,this.y=e.y/t,this.z=e.z/t),this}setAxisAngleFromRotationMatrix(e){let t,n,r,s,l=e.elements,h=l[0],d=l[4],m=l[8],f=l[1],v=l[5],S=l[9],E=l[2],_=l[6],g=l[10];if(Math.abs(d-f)<.01&&Math.abs(m-E)<.01&&Math.abs(S-_)<.01){if(Math.abs(d+f)<.1&&Math.abs(m+E)<.1&&Math.abs(S+_)<.1&&Math.abs(h+v+g-3)<.1)return this.set(1,0,0,0),this;t=Math.PI;let P=(h+1)/2,C=(v+1)/2,H=(g+1)/2,U=(d+f)/4,N=(m+E)/4,V=(S+_)/4;return P>C&&P>H?P<.01?(n=0,r=.707106781,s=.707106781):(n=Math.sqrt(P),r=U/n,s=N/n):C>H?C<.01?(n=.707106781,r=0,s=.707106781):(r=Math.sqrt(C),n=U/r,s=V/r):H<.01?(n=.707106781,r=.707106781,s=0):(s=Math.sqrt(H),n=N/s,r=V/s),this.set(n,r,s,t),this}let I=Math.sqrt((_-S)*(_-S)+(m-E)*(m-E)+(f-d)*(f-d));return Math.abs(I)<.001&&(I=1),this.x=(_-S)/I,this.y=(m-E)/I,this.z=(f-d)/I,this.w=Math.acos((h+v+g-1)/2),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this.w=t[15],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this.w=Math.min(this.w,e.w),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this.w=Math.max(this.w,e.w),this}clamp(e,t){return this.x=Math.max(e.x,Math.min(t.x,this.x)),this.y=Math.max(e.y,Math.min(t.y,this.y)),this.z=Math.max(e.z,Math.min(t.z,this.z)),this.w=Math.max(e.w,Math.min(t.w,this.w)),this}clampScalar(e,t){return this.x=Math.max(e,Math.min(t,this.x)),this.y=Math.max(e,Math.min(t,this.y)),this.z=Math.max(e,Math.min(t,this.z)),this.w=Math.max(e,Math.min(t,this.w)),this}clampLength(e,t){let n=this.length();return this.divideScalar(n||1).multiplyScalar(Math.max(e,Math.min(t,n)))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z+this.w*e.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this.w+=(e.w-this.w)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this.z=e.z+(t.z-e.z)*n,this.w=e.w+(t.w-e.w)*n,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z&&e.w===this.w}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this.w=e[t+3],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e[t+3]=this.w,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this.w=e.getW(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}},Oo=class extends Pn{constructor(e=1,t=1,n={}){super(),this.isRenderTarget=!0,this.width=e,this.height=t,this.depth=1,this.scissor=new gt(0,0,e,t),this.scissorTest=!1,this.viewport=new gt(0,0,e,t);let r={width:e,height:t,depth:1};n=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:fn,depthBuffer:!0,stencilBuffer:!1,resolveDepthBuffer:!0,resolveStencilBuffer:!0,depthTexture:null,samples:0,count:1},n);let s=new $t(r,n.mapping,n.wrapS,n.wrapT,n.magFilter,n.minFilter,n.format,n.type,n.anisotropy,n.colorSpace);s.flipY=!1,s.generateMipmaps=n.generateMipmaps,s.internalFormat=n.internalFormat,this.textures=[];let a=n.count;for(let o=0;o<a;o++)this.textures[o]=s.clone(),this.textures[o].isRenderTargetTexture=!0;this.depthBuffer=n.depthBuffer,this.stencilBuffer=n.stencilBuffer,this.resolveDepthBuffer=n.resolveDepthBuffer,this.resolveStencilBuffer=n.resolveStencilBuffer,this.depthTexture=n.depthTexture,this.samples=n.samples}get texture(){return this.textures[0]}set texture(e){this.textures[0]=e}setSize(e,t,n=1){if(this.width!==e||this.height!==t||this.depth!==n){this.width=e,this.height=t,this.depth=n;for(let r=0,s=this.textures.length;r<s;r++)this.textures[r].image.width=e,this.textures[r].image.height=t,this.textures[r].image.depth=n;this.dispose()}this.viewport.set(0,0,e,t),this.scissor.set(0,0,e,t)}clone(){return new this.constructor().copy(this)}copy(e){this.width=e.width,this.height=e.height,this.depth=e.depth,this.scissor.copy(e.scissor),this.scissorTest=e.scissorTest,this.viewport.copy(e.viewport),this.textures.length=0;for(let n=0,r=e.textures.length;n<r;n++)this.textures[n]=e.textures[n].clone(),this.textures[n].isRenderTargetTexture=!0;let t=Object.assign({},e.texture.image);return this.texture.source=new Ts(t),this.depthBuffer=e.depthBuffer,this.stencilBuffer=e.stencilBuffer,this.resolveDepthBuffer=e.resolveDepthBuffer,this.resolveStencilBuffer=e.resolveStencilBuffer,e.depthTexture!==null&&(this.depthTexture=e.depthTexture.clone()),this.samples=e.samples,this}dispose(){this.dispatchEvent({type:"dispose"})}},Ln=class extends Oo{constructor(e=1,t=1,n={}){super(e,t,n),this.isWebGLRenderTarget=!0}},As=class extends $t{constructor(e=null,t=1,n=1,r=1){super(null),this.isDataArrayTexture=!0,this.image={data:e,width:t,height:n,depth:r},this.magFilter=on,this.minFilter=on,this.wrapR=fi,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}addLayerUpdate(e){this.layerUpdates.add(e)}clearLayerUpdates(){this.layerUpdates.clear()}};var ko=class extends $t{constructor(e=null,t=1,n=1,r=1){super(null),this.isData3DTexture=!0,this.image={data:e,width:t,height:n,depth:r},this.magFilter=on,this.minFilter=on,this.wrapR=fi,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}};var ln=class{constructor(e=0,t=0,n=0,r=1){this.isQuaternion=!0,this._x=e,this._y=t,this._z=n,this._w=r}static slerpFlat(e,t,n,r,s,a,o){let l=n[r+0],h=n[r+1],d=n[r+2],m=n[r+3],f=s[a+0],v=s[a+1],S=s[a+2],E=s[a+3];if(o===0){e[t+0]=l,e[t+1]=h,e[t+2]=d,e[t+3]=m;return}if(o===1){e[t+0]=f,e[t+1]=v,e[t+2]=S,e[t+3]=E;return}if(m!==E||l!==f||h!==v||d!==S){let _=1-o,g=l*f+h*v+d*S+m*E,I=g>=0?1:-1,P=1-g*g;if(P>Number.EPSILON){let H=Math.sqrt(P),U=Math.atan2(H,g*I);_=Math.sin(_*U)/H,o=Math.sin(o*U)/H}let C=o*I;if(l=l*_+f*C,h=h*_+v*C,d=d*_+S*C,m=m*_+E*C,_===1-o){let H=1/Math.sqrt(l*l+h*h+d*d+m*m);l*=H,h*=H,d*=H,m*=H}}e[t]=l,e[t+1]=h,e[t+2]=d,e[t+3]=m}static multiplyQuaternionsFlat(e,t,n,r,s,a){let o=n[r],l=n[r+1],h=n[r+2],d=n[r+3],m=s[a],f=s[a+1],v=s[a+2],S=s[a+3];return e[t]=o*S+d*m+l*v-h*f,e[t+1]=l*S+d*f+h*m-o*v,e[t+2]=h*S+d*v+o*f-l*m,e[t+3]=d*S-o*m-l*f-h*v,e}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get w(){return this._w}set w(e){this._w=e,this._onChangeCallback()}set(e,t,n,r){return this._x=e,this._y=t,this._z=n,this._w=r,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(e){return this._x=e.x,this._y=e.y,this._z=e.z,this._w=e.w,this._onChangeCallback(),this}setFromEuler(e,t=!0){let n=e._x,r=e._y,s=e._z,a=e._order,o=Math.cos,l=Math.sin,h=o(n/2),d=o(r/2),m=o(s/2),f=l(n/2),v=l(r/2),S=l(s/2);switch(a){case"XYZ":this._x=f*d*m+h*v*S,this._y=h*v*m-f*d*S,this._z=h*d*S+f*v*m,this._w=h*d*m-f*v*S;break;case"YXZ":this._x=f*d*m+h*v*S,this._y=h*v*m-f*d*S,this._z=h*d*S-f*v*m,this._w=h*d*m+f*v*S;break;case"ZXY":this._x=f*d*m-h*v*S,this._y=h*v*m+f*d*S,this._z=h*d*S+f*v*m,this._w=h*d*m-f*v*S;break;case"ZYX":this._x=f*d*m-h*v*S,this._y=h*v*m+f*d*S,this._z=h*d*S-f*v*m,this._w=h*d*m+f*v*S;break;case"YZX":this._x=f*d*m+h*v*S,this._y=h*v*m+f*d*S,this._z=h*d*S-f*v*m,this._w=h*d*m-f*v*S;break;case"XZY":this._x=f*d*m-h*v*S,this._y=h*v*m-f*d*S,this._z=h*d*S+f*v*m,this._w=h*d*m+f*v*S;break;default:console.warn("THREE.Quaternion: .setFromEuler() encountered an unknown order: "+a)}return t===!0&&this._onChangeCallback(),this}setFromAxisAngle(e,t){let n=t/2,r=Math.sin(n);return this._x=e.x*r,this._y=e.y*r,this._z=e.z*r,this._w=Math.cos(n),this._onChangeCallback(),this}setFromRotationMatrix(e){let t=e.elements,n=t[0],r=t[4],s=t[8],a=t[1],o=t[5],l=t[9],h=t[2],d=t[6],m=t[10],f=n+o+m;if(f>0){let v=.5/Math.sqrt(f+1);this._w=.25/v,this._x=(d-l)*v,this._y=(s-h)*v,this._z=(a-r)*v}else if(n>o&&n>m){let v=2*Math.sqrt(1+n-o-m);this._w=(d-l)/v,this._x=.25*v,this._y=(r+a)/v,this._z=(s+h)/v}else if(o>m){let v=2*Math.sqrt(1+o-n-m);this._w=(s-h)/v,this._x=(r+a)/v,this._y=.25*v,this._z=(l+d)/v}else{let v=2*Math.sqrt(1+m-n-o);this._w=(a-r)/v,this._x=(s+h)/v,this._y=(l+d)/v,this._z=.25*v}return this._onChangeCallback(),this}setFromUnitVectors(e,t){let n=e.dot(t)+1;return n<Number.EPSILON?(n=0,Math.abs(e.x)>Math.abs(e.z)?(this._x=-e.y,this._y=e.x,this._z=0,this._w=n):(this._x=0,this._y=-e.z,this._z=e.y,this._w=n)):(this._x=e.y*t.z-e.z*t.y,this._y=e.z*t.x-e.x*t.z,this._z=e.x*t.y-e.y*t.x,this._w=n),this.normalize()}angleTo(e){return 2*Math.acos(Math.abs(Rt(this.dot(e),-1,1)))}rotateTowards(e,t){let n=this.angleTo(e);if(n===0)return this;let r=Math.min(1,t/n);return this.slerp(e,r),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(e){return this._x*e._x+this._y*e._y+this._z*e._z+this._w*e._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let e=this.length();return e===0?(this._x=0,this._y=0,this._z=0,this._w=1):(e=1/e,this._x=this._x*e,this._y=this._y*e,this._z=this._z*e,this._w=this._w*e),this._onChangeCallback(),this}multiply(e){return this.multiplyQuaternions(this,e)}premultiply(e){return this.multiplyQuaternions(e,this)}multiplyQuaternions(e,t){let n=e._x,r=e._y,s=e._z,a=e._w,o=t._x,l=t._y,h=t._z,d=t._w;return this._x=n*d+a*o+r*h-s*l,this._y=r*d+a*l+s*o-n*h,this._z=s*d+a*h+n*l-r*o,this._w=a*d-n*o-r*l-s*h,this._onChangeCallback(),this}slerp(e,t){if(t===0)return this;if(t===1)return this.copy(e);let n=this._x,r=this._y,s=this._z,a=this._w,o=a*e._w+n*e._x+r*e._y+s*e._z;if(o<0?(this._w=-e._w,this._x=-e._x,this._y=-e._y,this._z=-e._z,o=-o):this.copy(e),o>=1)return this._w=a,this._x=n,this._y=r,this._z=s,this;let l=1-o*o;if(l<=Number.EPSILON){let v=1-t;return this._w=v*a+t*this._w,this._x=v*n+t*this._x,this._y=v*r+t*this._y,this._z=v*s+t*this._z,this.normalize(),this}let h=Math.sqrt(l),d=Math.atan2(h,o),m=Math.sin((1-t)*d)/h,f=Math.sin(t*d)/h;return this._w=a*m+this._w*f,this._x=n*m+this._x*f,this._y=r*m+this._y*f,this._z=s*m+this._z*f,this._onChangeCallback(),this}slerpQuaternions(e,t,n){return this.copy(e).slerp(t,n)}random(){let e=2*Math.PI*Math.random(),t=2*Math.PI*Math.random(),n=Math.random(),r=Math.sqrt(1-n),s=Math.sqrt(n);return this.set(r*Math.sin(e),r*Math.cos(e),s*Math.sin(t),s*Math.cos(t))}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._w===this._w}fromArray(e,t=0){return this._x=e[t],this._y=e[t+1],this._z=e[t+2],this._w=e[t+3],this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._w,e}fromBufferAttribute(e,t){return this._x=e.getX(t),this._y=e.getY(t),this._z=e.getZ(t),this._w=e.getW(t),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}},X=class i{constructor(e=0,t=0,n=0){i.prototype.isVector3=!0,this.x=e,this.y=t,this.z=n}set(e,t,n){return n===void 0&&(n=this.z),this.x=e,this.y=t,this.z=n,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;default:throw new Error("index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this}multiplyVectors(e,t){return this.x=e.x*t.x,this.y=e.y*t.y,this.z=e.z*t.z,this}applyEuler(e){return this.applyQuaternion(Jl.setFromEuler(e))}applyAxisAngle(e,t){return this.applyQuaternion(Jl.setFromAxisAngle(e,t))}applyMatrix3(e){let t=this.x,n=this.y,r=this.z,s=e.elements;return this.x=s[0]*t+s[3]*n+s[6]*r,this.y=s[1]*t+s[4]*n+s[7]*r,this.z=s[2]*t+s[5]*n+s[8]*r,this}applyNormalMatrix(e){return this.applyMatrix3(e).normalize()}applyMatrix4(e){let t=this.x,n=this.y,r=this.z,s=e.elements,a=1/(s[3]*t+s[7]*n+s[11]*r+s[15]);return this.x=(s[0]*t+s[4]*n+s[8]*r+s[12])*a,this.y=(s[1]*t+s[5]*n+s[9]*r+s[13])*a,this.z=(s[2]*t+s[6]*n+s[10]*r+s[14])*a,this}applyQuaternion(e){let t=this.x,n=this.y,r=this.z,s=e.x,a=e.y,o=e.z,l=e.w,h=2*(a*r-o*n),d=2*(o*t-s*r),m=2*(s*n-a*t);return this.x=t+l*h+a*m-o*d,this.y=n+l*d+o*h-s*m,this.z=r+l*m+s*d-a*h,this}project(e){return this.applyMatrix4(e.matrixWorldInverse).applyMatrix4(e.projectionMatrix)}unproject(e){return this.applyMatrix4(e.projectionMatrixInverse).applyMatrix4(e.matrixWorld)}transformDirection(e){let t=this.x,n=this.y,r=this.z,s=e.elements;return this.x=s[0]*t+s[4]*n+s[8]*r,this.y=s[1]*t+s[5]*n+s[9]*r,this.z=s[2]*t+s[6]*n+s[10]*r,this.normalize()}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this}divideScalar(e){return this.multiplyScalar(1/e)}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this}clamp(e,t){return this.x=Math.max(e.x,Math.min(t.x,this.x)),this.y=Math.max(e.y,Math.min(t.y,this.y)),this.z=Math.max(e.z,Math.min(t.z,this.z)),this}clampScalar(e,t){return this.x=Math.max(e,Math.min(t,this.x)),this.y=Math.max(e,Math.min(t,this.y)),this.z=Math.max(e,Math.min(t,this.z)),this}clampLength(e,t){let n=this.length();return this.divideScalar(n||1).multiplyScalar(Math.max(e,Math.min(t,n)))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this.z=e.z+(t.z-e.z)*n,this}cross(e){return this.crossVectors(this,e)}crossVectors(e,t){let n=e.x,r=e.y,s=e.z,a=t.x,o=t.y,l=t.z;return this.x=r*l-s*o,this.y=s*a-n*l,this.z=n*o-r*a,this}projectOnVector(e){let t=e.lengthSq();if(t===0)return this.set(0,0,0);let n=e.dot(this)/t;return this.copy(e).multiplyScalar(n)}projectOnPlane(e){return Ea.copy(this).projectOnVector(e),this.sub(Ea)}reflect(e){return this.sub(Ea.copy(e).multiplyScalar(2*this.dot(e)))}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let n=this.dot(e)/t;return Math.acos(Rt(n,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,n=this.y-e.y,r=this.z-e.z;return t*t+n*n+r*r}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)+Math.abs(this.z-e.z)}setFromSpherical(e){return this.setFromSphericalCoords(e.radius,e.phi,e.theta)}setFromSphericalCoords(e,t,n){let r=Math.sin(t)*e;return this.x=r*Math.sin(n),this.y=Math.cos(t)*e,this.z=r*Math.cos(n),this}setFromCylindrical(e){return this.setFromCylindricalCoords(e.radius,e.theta,e.y)}setFromCylindricalCoords(e,t,n){return this.x=e*Math.sin(t),this.y=n,this.z=e*Math.cos(t),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this}setFromMatrixScale(e){let t=this.setFromMatrixColumn(e,0).length(),n=this.setFromMatrixColumn(e,1).length(),r=this.setFromMatrixColumn(e,2).length();return this.x=t,this.y=n,this.z=r,this}setFromMatrixColumn(e,t){return this.fromArray(e.elements,t*4)}setFromMatrix3Column(e,t){return this.fromArray(e.elements,t*3)}setFromEuler(e){return this.x=e._x,this.y=e._y,this.z=e._z,this}setFromColor(e){return this.x=e.r,this.y=e.g,this.z=e.b,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){let e=Math.random()*Math.PI*2,t=Math.random()*2-1,n=Math.sqrt(1-t*t);return this.x=n*Math.cos(e),this.y=t,this.z=n*Math.sin(e),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}},Ea=new X,Jl=new ln,In=class{constructor(e=new X(1/0,1/0,1/0),t=new X(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=e,this.max=t}set(e,t){return this.min.copy(e),this.max.copy(t),this}setFromArray(e){this.makeEmpty();for(let t=0,n=e.length;t<n;t+=3)this.expandByPoint(en.fromArray(e,t));return this}setFromBufferAttribute(e){this.makeEmpty();for(let t=0,n=e.count;t<n;t++)this.expandByPoint(en.fromBufferAttribute(e,t));return this}setFromPoints(e){this.makeEmpty();for(let t=0,n=e.length;t<n;t++)this.expandByPoint(e[t]);return this}setFromCenterAndSize(e,t){let n=en.copy(t).multiplyScalar(.5);return this.min.copy(e).sub(n),this.max.copy(e).add(n),this}setFromObject(e,t=!1){return this.makeEmpty(),this.expandByObject(e,t)}clone(){return new this.constructor().copy(this)}copy(e){return this.min.copy(e.min),this.max.copy(e.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(e){return this.isEmpty()?e.set(0,0,0):e.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(e){return this.isEmpty()?e.set(0,0,0):e.subVectors(this.max,this.min)}expandByPoint(e){return this.min.min(e),this.max.max(e),this}expandByVector(e){return this.min.sub(e),this.max.add(e),this}expandByScalar(e){return this.min.addScalar(-e),this.max.addScalar(e),this}expandByObject(e,t=!1){e.updateWorldMatrix(!1,!1);let n=e.geometry;if(n!==void 0){let s=n.getAttribute("position");if(t===!0&&s!==void 0&&e.isInstancedMesh!==!0)for(let a=0,o=s.count;a<o;a++)e.isMesh===!0?e.getVertexPosition(a,en):en.fromBufferAttribute(s,a),en.applyMatrix4(e.matrixWorld),this.expandByPoint(en);else e.boundingBox!==void 0?(e.boundingBox===null&&e.computeBoundingBox(),$r.copy(e.boundingBox)):(n.boundingBox===null&&n.computeBoundingBox(),$r.copy(n.boundingBox)),$r.applyMatrix4(e.matrixWorld),this.union($r)}let r=e.children;for(let s=0,a=r.length;s<a;s++)this.expandByObject(r[s],t);return this}containsPoint(e){return e.x>=this.min.x&&e.x<=this.max.x&&e.y>=this.min.y&&e.y<=this.max.y&&e.z>=this.min.z&&e.z<=this.max.z}containsBox(e){return this.min.x<=e.min.x&&e.max.x<=this.max.x&&this.min.y<=e.min.y&&e.max.y<=this.max.y&&this.min.z<=e.min.z&&e.max.z<=this.max.z}getParameter(e,t){return t.set((e.x-this.min.x)/(this.max.x-this.min.x),(e.y-this.min.y)/(this.max.y-this.min.y),(e.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(e){return e.max.x>=this.min.x&&e.min.x<=this.max.x&&e.max.y>=this.min.y&&e.min.y<=this.max.y&&e.max.z>=this.min.z&&e.min.z<=this.max.z}intersectsSphere(e){return this.clampPoint(e.center,en),en.distanceToSquared(e.center)<=e.radius*e.radius}intersectsPlane(e){let t,n;return e.normal.x>0?(t=e.normal.x*this.min.x,n=e.normal.x*this.max.x):(t=e.normal.x*this.max.x,n=e.normal.x*this.min.x),e.normal.y>0?(t+=e.normal.y*this.min.y,n+=e.normal.y*this.max.y):(t+=e.normal.y*this.max.y,n+=e.normal.y*this.min.y),e.normal.z>0?(t+=e.normal.z*this.min.z,n+=e.normal.z*this.max.z):(t+=e.normal.z*this.max.z,n+=e.normal.z*this.min.z),t<=-e.constant&&n>=-e.constant}intersectsTriangle(e){if(this.isEmpty())return!1;this.getCenter(_r),Kr.subVectors(this.max,_r),Ri.subVectors(e.a,_r),Pi.subVectors(e.b,_r),Li.subVectors(e.c,_r),Gn.subVectors(Pi,Ri),Vn.subVectors(Li,Pi),ii.subVectors(Ri,Li);let t=[0,-Gn.z,Gn.y,0,-Vn.z,Vn.y,0,-ii.z,ii.y,Gn.z,0,-Gn.x,Vn.z,0,-Vn.x,ii.z,0,-ii.x,-Gn.y,Gn.x,0,-Vn.y,Vn.x,0,-ii.y,ii.x,0];return!Ta(t,Ri,Pi,Li,Kr)||(t=[1,0,0,0,1,0,0,0,1],!Ta(t,Ri,Pi,Li,Kr))?!1:(jr.crossVectors(Gn,Vn),t=[jr.x,jr.y,jr.z],Ta(t,Ri,Pi,Li,Kr))}clampPoint(e,t){return t.copy(e).clamp(this.min,this.max)}distanceToPoint(e){return this.clampPoint(e,en).distanceTo(e)}getBoundingSphere(e){return this.isEmpty()?e.makeEmpty():(this.getCenter(e.center),e.radius=this.getSize(en).length()*.5),e}intersect(e){return this.min.max(e.min),this.max.min(e.max),this.isEmpty()&&this.makeEmpty(),this}union(e){return this.min.min(e.min),this.max.max(e.max),this}applyMatrix4(e){return this.isEmpty()?this:(yn[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(e),yn[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(e),yn[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(e),yn[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(e),yn[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(e),yn[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(e),yn[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(e),yn[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(e),this.setFromPoints(yn),this)}translate(e){return this.min.add(e),this.max.add(e),this}equals(e){return e.min.equals(this.min)&&e.max.equals(this.max)}},yn=[new X,new X,new X,new X,new X,new X,new X,new X],en=new X,$r=new In,Ri=new X,Pi=new X,Li=new X,Gn=new X,Vn=new X,ii=new X,_r=new X,Kr=new X,jr=new X,ri=new X;function Ta(i,e,t,n,r){for(let s=0,a=i.length-3;s<=a;s+=3){ri.fromArray(i,s);let o=r.x*Math.abs(ri.x)+r.y*Math.abs(ri.y)+r.z*Math.abs(ri.z),l=e.dot(ri),h=t.dot(ri),d=n.dot(ri);if(Math.max(-Math.max(l,h,d),Math.min(l,h,d))>o)return!1}return!0}var Qf=new In,yr=new X,Aa=new X,Qi=class{constructor(e=new X,t=-1){this.isSphere=!0,this.center=e,this.radius=t}set(e,t){return this.center.copy(e),this.radius=t,this}setFromPoints(e,t){let n=this.center;t!==void 0?n.copy(t):Qf.setFromPoints(e).getCenter(n);let r=0;for(let s=0,a=e.length;s<a;s++)r=Math.max(r,n.distanceToSquared(e[s]));return this.radius=Math.sqrt(r),this}copy(e){return this.center.copy(e.center),this.radius=e.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(e){return e.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(e){return e.distanceTo(this.center)-this.radius}intersectsSphere(e){let t=this.radius+e.radius;return e.center.distanceToSquared(this.center)<=t*t}intersectsBox(e){return e.intersectsSphere(this)}intersectsPlane(e){return Math.abs(e.distanceToPoint(this.center))<=this.radius}clampPoint(e,t){let n=this.center.distanceToSquared(e);return t.copy(e),n>this.radius*this.radius&&(t.sub(this.center).normalize(),t.multiplyScalar(this.radius).add(this.center)),t}getBoundingBox(e){return this.isEmpty()?(e.makeEmpty(),e):(e.set(this.center,this.center),e.expandByScalar(this.radius),e)}applyMatrix4(e){return this.center.applyMatrix4(e),this.radius=this.radius*e.getMaxScaleOnAxis(),this}translate(e){return this.center.add(e),this}expandByPoint(e){if(this.isEmpty())return this.center.copy(e),this.radius=0,this;yr.subVectors(e,this.center);let t=yr.lengthSq();if(t>this.radius*this.radius){let n=Math.sqrt(t),r=(n-this.radius)*.5;this.center.addScaledVector(yr,r/n),this.radius+=r}return this}union(e){return e.isEmpty()?this:this.isEmpty()?(this.copy(e),this):(this.center.equals(e.center)===!0?this.radius=Math.max(this.radius,e.radius):(Aa.subVectors(e.center,this.center).setLength(e.radius),this.expandByPoint(yr.copy(e.center).add(Aa)),this.expandByPoint(yr.copy(e.center).sub(Aa))),this)}equals(e){return e.center.equals(this.center)&&e.radius===this.radius}clone(){return new this.constructor().copy(this)}},xn=new X,Ca=new X,Jr=new X,Hn=new X,Ra=new X,Qr=new X,Pa=new X,er=class{constructor(e=new X,t=new X(0,0,-1)){this.origin=e,this.direction=t}set(e,t){return this.origin.copy(e),this.direction.copy(t),this}copy(e){return this.origin.copy(e.origin),this.direction.copy(e.direction),this}at(e,t){return t.copy(this.origin).addScaledVector(this.direction,e)}lookAt(e){return this.direction.copy(e).sub(this.origin).normalize(),this}recast(e){return this.origin.copy(this.at(e,xn)),this}closestPointToPoint(e,t){t.subVectors(e,this.origin);let n=t.dot(this.direction);return n<0?t.copy(this.origin):t.copy(this.origin).addScaledVector(this.direction,n)}distanceToPoint(e){return Math.sqrt(this.distanceSqToPoint(e))}distanceSqToPoint(e){let t=xn.subVectors(e,this.origin).dot(this.direction);return t<0?this.origin.distanceToSquared(e):(xn.copy(this.origin).addScaledVector(this.direction,t),xn.distanceToSquared(e))}distanceSqToSegment(e,t,n,r){Ca.copy(e).add(t).multiplyScalar(.5),Jr.copy(t).sub(e).normalize(),Hn.copy(this.origin).sub(Ca);let s=e.distanceTo(t)*.5,a=-this.direction.dot(Jr),o=Hn.dot(this.direction),l=-Hn.dot(Jr),h=Hn.lengthSq(),d=Math.abs(1-a*a),m,f,v,S;if(d>0)if(m=a*l-o,f=a*o-l,S=s*d,m>=0)if(f>=-S)if(f<=S){let E=1/d;m*=E,f*=E,v=m*(m+a*f+2*o)+f*(a*m+f+2*l)+h}else f=s,m=Math.max(0,-(a*f+o)),v=-m*m+f*(f+2*l)+h;else f=-s,m=Math.max(0,-(a*f+o)),v=-m*m+f*(f+2*l)+h;else f<=-S?(m=Math.max(0,-(-a*s+o)),f=m>0?-s:Math.min(Math.max(-s,-l),s),v=-m*m+f*(f+2*l)+h):f<=S?(m=0,f=Math.min(Math.max(-s,-l),s),v=f*(f+2*l)+h):(m=Math.max(0,-(a*s+o)),f=m>0?s:Math.min(Math.max(-s,-l),s),v=-m*m+f*(f+2*l)+h);else f=a>0?-s:s,m=Math.max(0,-(a*f+o)),v=-m*m+f*(f+2*l)+h;return n&&n.copy(this.origin).addScaledVector(this.direction,m),r&&r.copy(Ca).addScaledVector(Jr,f),v}intersectSphere(e,t){xn.subVectors(e.center,this.origin);let n=xn.dot(this.direction),r=xn.dot(xn)-n*n,s=e.radius*e.radius;if(r>s)return null;let a=Math.sqrt(s-r),o=n-a,l=n+a;return l<0?null:o<0?this.at(l,t):this.at(o,t)}intersectsSphere(e){return this.distanceSqToPoint(e.center)<=e.radius*e.radius}distanceToPlane(e){let t=e.normal.dot(this.direction);if(t===0)return e.distanceToPoint(this.origin)===0?0:null;let n=-(this.origin.dot(e.normal)+e.constant)/t;return n>=0?n:null}intersectPlane(e,t){let n=this.distanceToPlane(e);return n===null?null:this.at(n,t)}intersectsPlane(e){let t=e.distanceToPoint(this.origin);return t===0||e.normal.dot(this.direction)*t<0}intersectBox(e,t){let n,r,s,a,o,l,h=1/this.direction.x,d=1/this.direction.y,m=1/this.direction.z,f=this.origin;return h>=0?(n=(e.min.x-f.x)*h,r=(e.max.x-f.x)*h):(n=(e.max.x-f.x)*h,r=(e.min.x-f.x)*h),d>=0?(s=(e.min.y-f.y)*d,a=(e.max.y-f.y)*d):(s=(e.max.y-f.y)*d,a=(e.min.y-f.y)*d),n>a||s>r||((s>n||isNaN(n))&&(n=s),(a<r||isNaN(r))&&(r=a),m>=0?(o=(e.min.z-f.z)*m,l=(e.max.z-f.z)*m):(o=(e.max.z-f.z)*m,l=(e.min.z-f.z)*m),n>l||o>r)||((o>n||n!==n)&&(n=o),(l<r||r!==r)&&(r=l),r<0)?null:this.at(n>=0?n:r,t)}intersectsBox(e){return this.intersectBox(e,xn)!==null}intersectTriangle(e,t,n,r,s){Ra.subVectors(t,e),Qr.subVectors(n,e),Pa.crossVectors(Ra,Qr);let a=this.direction.dot(Pa),o;if(a>0){if(r)return null;o=1}else if(a<0)o=-1,a=-a;else return null;Hn.subVectors(this.origin,e);let l=o*this.direction.dot(Qr.crossVectors(Hn,Qr));if(l<0)return null;let h=o*this.direction.dot(Ra.cross(Hn));if(h<0||l+h>a)return null;let d=-o*Hn.dot(Pa);return d<0?null:this.at(d/a,s)}applyMatrix4(e){return this.origin.applyMatrix4(e),this.direction.transformDirection(e),this}equals(e){return e.origin.equals(this.origin)&&e.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}},_t=class i{constructor(e,t,n,r,s,a,o,l,h,d,m,f,v,S,E,_){i.prototype.isMatrix4=!0,this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],e!==void 0&&this.set(e,t,n,r,s,a,o,l,h,d,m,f,v,S,E,_)}set(e,t,n,r,s,a,o,l,h,d,m,f,v,S,E,_){let g=this.elements;return g[0]=e,g[4]=t,g[8]=n,g[12]=r,g[1]=s,g[5]=a,g[9]=o,g[13]=l,g[2]=h,g[6]=d,g[10]=m,g[14]=f,g[3]=v,g[7]=S,g[11]=E,g[15]=_,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new i().fromArray(this.elements)}copy(e){let t=this.elements,n=e.elements;return t[0]=n[0],t[1]=n[1],t[2]=n[2],t[3]=n[3],t[4]=n[4],t[5]=n[5],t[6]=n[6],t[7]=n[7],t[8]=n[8],t[9]=n[9],t[10]=n[10],t[11]=n[11],t[12]=n[12],t[13]=n[13],t[14]=n[14],t[15]=n[15],this}copyPosition(e){let t=this.elements,n=e.elements;return t[12]=n[12],t[13]=n[13],t[14]=n[14],this}setFromMatrix3(e){let t=e.elements;return this.set(t[0],t[3],t[6],0,t[1],t[4],t[7],0,t[2],t[5],t[8],0,0,0,0,1),this}extractBasis(e,t,n){return e.setFromMatrixColumn(this,0),t.setFromMatrixColumn(this,1),n.setFromMatrixColumn(this,2),this}makeBasis(e,t,n){return this.set(e.x,t.x,n.x,0,e.y,t.y,n.y,0,e.z,t.z,n.z,0,0,0,0,1),this}extractRotation(e){let t=this.elements,n=e.elements,r=1/Ii.setFromMatrixColumn(e,0).length(),s=1/Ii.setFromMatrixColumn(e,1).length(),a=1/Ii.setFromMatrixColumn(e,2).length();return t[0]=n[0]*r,t[1]=n[1]*r,t[2]=n[2]*r,t[3]=0,t[4]=n[4]*s,t[5]=n[5]*s,t[6]=n[6]*s,t[7]=0,t[8]=n[8]*a,t[9]=n[9]*a,t[10]=n[10]*a,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromEuler(e){let t=this.elements,n=e.x,r=e.y,s=e.z,a=Math.cos(n),o=Math.sin(n),l=Math.cos(r),h=Math.sin(r),d=Math.cos(s),m=Math.sin(s);if(e.order==="XYZ"){let f=a*d,v=a*m,S=o*d,E=o*m;t[0]=l*d,t[4]=-l*m,t[8]=h,t[1]=v+S*h,t[5]=f-E*h,t[9]=-o*l,t[2]=E-f*h,t[6]=S+v*h,t[10]=a*l}else if(e.order==="YXZ"){let f=l*d,v=l*m,S=h*d,E=h*m;t[0]=f+E*o,t[4]=S*o-v,t[8]=a*h,t[1]=a*m,t[5]=a*d,t[9]=-o,t[2]=v*o-S,t[6]=E+f*o,t[10]=a*l}else if(e.order==="ZXY"){let f=l*d,v=l*m,S=h*d,E=h*m;t[0]=f-E*o,t[4]=-a*m,t[8]=S+v*o,t[1]=v+S*o,t[5]=a*d,t[9]=E-f*o,t[2]=-a*h,t[6]=o,t[10]=a*l}else if(e.order==="ZYX"){let f=a*d,v=a*m,S=o*d,E=o*m;t[0]=l*d,t[4]=S*h-v,t[8]=f*h+E,t[1]=l*m,t[5]=E*h+f,t[9]=v*h-S,t[2]=-h,t[6]=o*l,t[10]=a*l}else if(e.order==="YZX"){let f=a*l,v=a*h,S=o*l,E=o*h;t[0]=l*d,t[4]=E-f*m,t[8]=S*m+v,t[1]=m,t[5]=a*d,t[9]=-o*d,t[2]=-h*d,t[6]=v*m+S,t[10]=f-E*m}else if(e.order==="XZY"){let f=a*l,v=a*h,S=o*l,E=o*h;t[0]=l*d,t[4]=-m,t[8]=h*d,t[1]=f*m+E,t[5]=a*d,t[9]=v*m-S,t[2]=S*m-v,t[6]=o*d,t[10]=E*m+f}return t[3]=0,t[7]=0,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromQuaternion(e){return this.compose(ep,e,tp)}lookAt(e,t,n){let r=this.elements;return Gt.subVectors(e,t),Gt.lengthSq()===0&&(Gt.z=1),Gt.normalize(),Wn.crossVectors(n,Gt),Wn.lengthSq()===0&&(Math.abs(n.z)===1?Gt.x+=1e-4:Gt.z+=1e-4,Gt.normalize(),Wn.crossVectors(n,Gt)),Wn.normalize(),es.crossVectors(Gt,Wn),r[0]=Wn.x,r[4]=es.x,r[8]=Gt.x,r[1]=Wn.y,r[5]=es.y,r[9]=Gt.y,r[2]=Wn.z,r[6]=es.z,r[10]=Gt.z,this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let n=e.elements,r=t.elements,s=this.elements,a=n[0],o=n[4],l=n[8],h=n[12],d=n[1],m=n[5],f=n[9],v=n[13],S=n[2],E=n[6],_=n[10],g=n[14],I=n[3],P=n[7],C=n[11],H=n[15],U=r[0],N=r[4],V=r[8],L=r[12],R=r[1],F=r[5],Q=r[9],Z=r[13],J=r[2],ie=r[6],$=r[10],ue=r[14],j=r[3],ge=r[7],_e=r[11],Ce=r[15];return s[0]=a*U+o*R+l*J+h*j,s[4]=a*N+o*F+l*ie+h*ge,s[8]=a*V+o*Q+l*$+h*_e,s[12]=a*L+o*Z+l*ue+h*Ce,s[1]=d*U+m*R+f*J+v*j,s[5]=d*N+m*F+f*ie+v*ge,s[9]=d*V+m*Q+f*$+v*_e,s[13]=d*L+m*Z+f*ue+v*Ce,s[2]=S*U+E*R+_*J+g*j,s[6]=S*N+E*F+_*ie+g*ge,s[10]=S*V+E*Q+_*$+g*_e,s[14]=S*L+E*Z+_*ue+g*Ce,s[3]=I*U+P*R+C*J+H*j,s[7]=I*N+P*F+C*ie+H*ge,s[11]=I*V+P*Q+C*$+H*_e,s[15]=I*L+P*Z+C*ue+H*Ce,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[4]*=e,t[8]*=e,t[12]*=e,t[1]*=e,t[5]*=e,t[9]*=e,t[13]*=e,t[2]*=e,t[6]*=e,t[10]*=e,t[14]*=e,t[3]*=e,t[7]*=e,t[11]*=e,t[15]*=e,this}determinant(){let e=this.elements,t=e[0],n=e[4],r=e[8],s=e[12],a=e[1],o=e[5],l=e[9],h=e[13],d=e[2],m=e[6],f=e[10],v=e[14],S=e[3],E=e[7],_=e[11],g=e[15];return S*(+s*l*m-r*h*m-s*o*f+n*h*f+r*o*v-n*l*v)+E*(+t*l*v-t*h*f+s*a*f-r*a*v+r*h*d-s*l*d)+_*(+t*h*m-t*o*v-s*a*m+n*a*v+s*o*d-n*h*d)+g*(-r*o*d-t*l*m+t*o*f+r*a*m-n*a*f+n*l*d)}transpose(){let e=this.elements,t;return t=e[1],e[1]=e[4],e[4]=t,t=e[2],e[2]=e[8],e[8]=t,t=e[6],e[6]=e[9],e[9]=t,t=e[3],e[3]=e[12],e[12]=t,t=e[7],e[7]=e[13],e[13]=t,t=e[11],e[11]=e[14],e[14]=t,this}setPosition(e,t,n){let r=this.elements;return e.isVector3?(r[12]=e.x,r[13]=e.y,r[14]=e.z):(r[12]=e,r[13]=t,r[14]=n),this}invert(){let e=this.elements,t=e[0],n=e[1],r=e[2],s=e[3],a=e[4],o=e[5],l=e[6],h=e[7],d=e[8],m=e[9],f=e[10],v=e[11],S=e[12],E=e[13],_=e[14],g=e[15],I=m*_*h-E*f*h+E*l*v-o*_*v-m*l*g+o*f*g,P=S*f*h-d*_*h-S*l*v+a*_*v+d*l*g-a*f*g,C=d*E*h-S*m*h+S*o*v-a*E*v-d*o*g+a*m*g,H=S*m*l-d*E*l-S*o*f+a*E*f+d*o*_-a*m*_,U=t*I+n*P+r*C+s*H;if(U===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);let N=1/U;return e[0]=I*N,e[1]=(E*f*s-m*_*s-E*r*v+n*_*v+m*r*g-n*f*g)*N,e[2]=(o*_*s-E*l*s+E*r*h-n*_*h-o*r*g+n*l*g)*N,e[3]=(m*l*s-o*f*s-m*r*h+n*f*h+o*r*v-n*l*v)*N,e[4]=P*N,e[5]=(d*_*s-S*f*s+S*r*v-t*_*v-d*r*g+t*f*g)*N,e[6]=(S*l*s-a*_*s-S*r*h+t*_*h+a*r*g-t*l*g)*N,e[7]=(a*f*s-d*l*s+d*r*h-t*f*h-a*r*v+t*l*v)*N,e[8]=C*N,e[9]=(S*m*s-d*E*s-S*n*v+t*E*v+d*n*g-t*m*g)*N,e[10]=(a*E*s-S*o*s+S*n*h-t*E*h-a*n*g+t*o*g)*N,e[11]=(d*o*s-a*m*s-d*n*h+t*m*h+a*n*v-t*o*v)*N,e[12]=H*N,e[13]=(d*E*r-S*m*r+S*n*f-t*E*f-d*n*_+t*m*_)*N,e[14]=(S*o*r-a*E*r-S*n*l+t*E*l+a*n*_-t*o*_)*N,e[15]=(a*m*r-d*o*r+d*n*l-t*m*l-a*n*f+t*o*f)*N,this}scale(e){let t=this.elements,n=e.x,r=e.y,s=e.z;return t[0]*=n,t[4]*=r,t[8]*=s,t[1]*=n,t[5]*=r,t[9]*=s,t[2]*=n,t[6]*=r,t[10]*=s,t[3]*=n,t[7]*=r,t[11]*=s,this}getMaxScaleOnAxis(){let e=this.elements,t=e[0]*e[0]+e[1]*e[1]+e[2]*e[2],n=e[4]*e[4]+e[5]*e[5]+e[6]*e[6],r=e[8]*e[8]+e[9]*e[9]+e[10]*e[10];return Math.sqrt(Math.max(t,n,r))}makeTranslation(e,t,n){return e.isVector3?this.set(1,0,0,e.x,0,1,0,e.y,0,0,1,e.z,0,0,0,1):this.set(1,0,0,e,0,1,0,t,0,0,1,n,0,0,0,1),this}makeRotationX(e){let t=Math.cos(e),n=Math.sin(e);return this.set(1,0,0,0,0,t,-n,0,0,n,t,0,0,0,0,1),this}makeRotationY(e){let t=Math.cos(e),n=Math.sin(e);return this.set(t,0,n,0,0,1,0,0,-n,0,t,0,0,0,0,1),this}makeRotationZ(e){let t=Math.cos(e),n=Math.sin(e);return this.set(t,-n,0,0,n,t,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(e,t){let n=Math.cos(t),r=Math.sin(t),s=1-n,a=e.x,o=e.y,l=e.z,h=s*a,d=s*o;return this.set(h*a+n,h*o-r*l,h*l+r*o,0,h*o+r*l,d*o+n,d*l-r*a,0,h*l-r*o,d*l+r*a,s*l*l+n,0,0,0,0,1),this}makeScale(e,t,n){return this.set(e,0,0,0,0,t,0,0,0,0,n,0,0,0,0,1),this}makeShear(e,t,n,r,s,a){return this.set(1,n,s,0,e,1,a,0,t,r,1,0,0,0,0,1),this}compose(e,t,n){let r=this.elements,s=t._x,a=t._y,o=t._z,l=t._w,h=s+s,d=a+a,m=o+o,f=s*h,v=s*d,S=s*m,E=a*d,_=a*m,g=o*m,I=l*h,P=l*d,C=l*m,H=n.x,U=n.y,N=n.z;return r[0]=(1-(E+g))*H,r[1]=(v+C)*H,r[2]=(S-P)*H,r[3]=0,r[4]=(v-C)*U,r[5]=(1-(f+g))*U,r[6]=(_+I)*U,r[7]=0,r[8]=(S+P)*N,r[9]=(_-I)*N,r[10]=(1-(f+E))*N,r[11]=0,r[12]=e.x,r[13]=e.y,r[14]=e.z,r[15]=1,this}decompose(e,t,n){let r=this.elements,s=Ii.set(r[0],r[1],r[2]).length(),a=Ii.set(r[4],r[5],r[6]).length(),o=Ii.set(r[8],r[9],r[10]).length();this.determinant()<0&&(s=-s),e.x=r[12],e.y=r[13],e.z=r[14],tn.copy(this);let h=1/s,d=1/a,m=1/o;return tn.elements[0]*=h,tn.elements[1]*=h,tn.elements[2]*=h,tn.elements[4]*=d,tn.elements[5]*=d,tn.elements[6]*=d,tn.elements[8]*=m,tn.elements[9]*=m,tn.elements[10]*=m,t.setFromRotationMatrix(tn),n.x=s,n.y=a,n.z=o,this}makePerspective(e,t,n,r,s,a,o=An){let l=this.elements,h=2*s/(t-e),d=2*s/(n-r),m=(t+e)/(t-e),f=(n+r)/(n-r),v,S;if(o===An)v=-(a+s)/(a-s),S=-2*a*s/(a-s);else if(o===ws)v=-a/(a-s),S=-a*s/(a-s);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+o);return l[0]=h,l[4]=0,l[8]=m,l[12]=0,l[1]=0,l[5]=d,l[9]=f,l[13]=0,l[2]=0,l[6]=0,l[10]=v,l[14]=S,l[3]=0,l[7]=0,l[11]=-1,l[15]=0,this}makeOrthographic(e,t,n,r,s,a,o=An){let l=this.elements,h=1/(t-e),d=1/(n-r),m=1/(a-s),f=(t+e)*h,v=(n+r)*d,S,E;if(o===An)S=(a+s)*m,E=-2*m;else if(o===ws)S=s*m,E=-1*m;else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+o);return l[0]=2*h,l[4]=0,l[8]=0,l[12]=-f,l[1]=0,l[5]=2*d,l[9]=0,l[13]=-v,l[2]=0,l[6]=0,l[10]=E,l[14]=-S,l[3]=0,l[7]=0,l[11]=0,l[15]=1,this}equals(e){let t=this.elements,n=e.elements;for(let r=0;r<16;r++)if(t[r]!==n[r])return!1;return!0}fromArray(e,t=0){for(let n=0;n<16;n++)this.elements[n]=e[n+t];return this}toArray(e=[],t=0){let n=this.elements;return e[t]=n[0],e[t+1]=n[1],e[t+2]=n[2],e[t+3]=n[3],e[t+4]=n[4],e[t+5]=n[5],e[t+6]=n[6],e[t+7]=n[7],e[t+8]=n[8],e[t+9]=n[9],e[t+10]=n[10],e[t+11]=n[11],e[t+12]=n[12],e[t+13]=n[13],e[t+14]=n[14],e[t+15]=n[15],e}},Ii=new X,tn=new _t,ep=new X(0,0,0),tp=new X(1,1,1),Wn=new X,es=new X,Gt=new X,Ql=new _t,eh=new ln,Dn=class i{constructor(e=0,t=0,n=0,r=i.DEFAULT_ORDER){this.isEuler=!0,this._x=e,this._y=t,this._z=n,this._order=r}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get order(){return this._order}set order(e){this._order=e,this._onChangeCallback()}set(e,t,n,r=this._order){return this._x=e,this._y=t,this._z=n,this._order=r,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(e){return this._x=e._x,this._y=e._y,this._z=e._z,this._order=e._order,this._onChangeCallback(),this}setFromRotationMatrix(e,t=this._order,n=!0){let r=e.elements,s=r[0],a=r[4],o=r[8],l=r[1],h=r[5],d=r[9],m=r[2],f=r[6],v=r[10];switch(t){case"XYZ":this._y=Math.asin(Rt(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(-d,v),this._z=Math.atan2(-a,s)):(this._x=Math.atan2(f,h),this._z=0);break;case"YXZ":this._x=Math.asin(-Rt(d,-1,1)),Math.abs(d)<.9999999?(this._y=Math.atan2(o,v),this._z=Math.atan2(l,h)):(this._y=Math.atan2(-m,s),this._z=0);break;case"ZXY":this._x=Math.asin(Rt(f,-1,1)),Math.abs(f)<.9999999?(this._y=Math.atan2(-m,v),this._z=Math.atan2(-a,h)):(this._y=0,this._z=Math.atan2(l,s));break;case"ZYX":this._y=Math.asin(-Rt(m,-1,1)),Math.abs(m)<.9999999?(this._x=Math.atan2(f,v),this._z=Math.atan2(l,s)):(this._x=0,this._z=Math.atan2(-a,h));break;case"YZX":this._z=Math.asin(Rt(l,-1,1)),Math.abs(l)<.9999999?(this._x=Math.atan2(-d,h),this._y=Math.atan2(-m,s)):(this._x=0,this._y=Math.atan2(o,v));break;case"XZY":this._z=Math.asin(-Rt(a,-1,1)),Math.abs(a)<.9999999?(this._x=Math.atan2(f,h),this._y=Math.atan2(o,s)):(this._x=Math.atan2(-d,v),this._y=0);break;default:console.warn("THREE.Euler: .setFromRotationMatrix() encountered an unknown order: "+t)}return this._order=t,n===!0&&this._onChangeCallback(),this}setFromQuaternion(e,t,n){return Ql.makeRotationFromQuaternion(e),this.setFromRotationMatrix(Ql,t,n)}setFromVector3(e,t=this._order){return this.set(e.x,e.y,e.z,t)}reorder(e){return eh.setFromEuler(this),this.setFromQuaternion(eh,e)}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._order===this._order}fromArray(e){return this._x=e[0],this._y=e[1],this._z=e[2],e[3]!==void 0&&(this._order=e[3]),this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._order,e}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}};Dn.DEFAULT_ORDER="XYZ";var Cs=class{constructor(){this.mask=1}set(e){this.mask=(1<<e|0)>>>0}enable(e){this.mask|=1<<e|0}enableAll(){this.mask=-1}toggle(e){this.mask^=1<<e|0}disable(e){this.mask&=~(1<<e|0)}disableAll(){this.mask=0}test(e){return(this.mask&e.mask)!==0}isEnabled(e){return(this.mask&(1<<e|0))!==0}},np=0,th=new X,Di=new ln,bn=new _t,ts=new X,xr=new X,ip=new X,rp=new ln,nh=new X(1,0,0),ih=new X(0,1,0),rh=new X(0,0,1),sh={type:"added"},sp={type:"removed"},Ni={type:"childadded",child:null},La={type:"childremoved",child:null},Kt=class i extends Pn{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:np++}),this.uuid=rr(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=i.DEFAULT_UP.clone();let e=new X,t=new Dn,n=new ln,r=new X(1,1,1);function s(){n.setFromEuler(t,!1)}function a(){t.setFromQuaternion(n,void 0,!1)}t._onChange(s),n._onChange(a),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:e},rotation:{configurable:!0,enumerable:!0,value:t},quaternion:{configurable:!0,enumerable:!0,value:n},scale:{configurable:!0,enumerable:!0,value:r},modelViewMatrix:{value:new _t},normalMatrix:{value:new He}}),this.matrix=new _t,this.matrixWorld=new _t,this.matrixAutoUpdate=i.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=i.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new Cs,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.userData={}}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(e){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(e),this.matrix.decompose(this.position,this.quaternion,this.scale)}applyQuaternion(e){return this.quaternion.premultiply(e),this}setRotationFromAxisAngle(e,t){this.quaternion.setFromAxisAngle(e,t)}setRotationFromEuler(e){this.quaternion.setFromEuler(e,!0)}setRotationFromMatrix(e){this.quaternion.setFromRotationMatrix(e)}setRotationFromQuaternion(e){this.quaternion.copy(e)}rotateOnAxis(e,t){return Di.setFromAxisAngle(e,t),this.quaternion.multiply(Di),this}rotateOnWorldAxis(e,t){return Di.setFromAxisAngle(e,t),this.quaternion.premultiply(Di),this}rotateX(e){return this.rotateOnAxis(nh,e)}rotateY(e){return this.rotateOnAxis(ih,e)}rotateZ(e){return this.rotateOnAxis(rh,e)}translateOnAxis(e,t){return th.copy(e).applyQuaternion(this.quaternion),this.position.add(th.multiplyScalar(t)),this}translateX(e){return this.translateOnAxis(nh,e)}translateY(e){return this.translateOnAxis(ih,e)}translateZ(e){return this.translateOnAxis(rh,e)}localToWorld(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(this.matrixWorld)}worldToLocal(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(bn.copy(this.matrixWorld).invert())}lookAt(e,t,n){e.isVector3?ts.copy(e):ts.set(e,t,n);let r=this.parent;this.updateWorldMatrix(!0,!1),xr.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?bn.lookAt(xr,ts,this.up):bn.lookAt(ts,xr,this.up),this.quaternion.setFromRotationMatrix(bn),r&&(bn.extractRotation(r.matrixWorld),Di.setFromRotationMatrix(bn),this.quaternion.premultiply(Di.invert()))}add(e){if(arguments.length>1){for(let t=0;t<arguments.length;t++)this.add(arguments[t]);return this}return e===this?(console.error("THREE.Object3D.add: object can't be added as a child of itself.",e),this):(e&&e.isObject3D?(e.removeFromParent(),e.parent=this,this.children.push(e),e.dispatchEvent(sh),Ni.child=e,this.dispatchEvent(Ni),Ni.child=null):console.error("THREE.Object3D.add: object not an instance of THREE.Object3D.",e),this)}remove(e){if(arguments.length>1){for(let n=0;n<arguments.length;n++)this.remove(arguments[n]);return this}let t=this.children.indexOf(e);return t!==-1&&(e.parent=null,this.children.splice(t,1),e.dispatchEvent(sp),La.child=e,this.dispatchEvent(La),La.child=null),this}removeFromParent(){let e=this.parent;return e!==null&&e.remove(this),this}clear(){return this.remove(...this.children)}attach(e){return this.updateWorldMatrix(!0,!1),bn.copy(this.matrixWorld).invert(),e.parent!==null&&(e.parent.updateWorldMatrix(!0,!1),bn.multiply(e.parent.matrixWorld)),e.applyMatrix4(bn),e.removeFromParent(),e.parent=this,this.children.push(e),e.updateWorldMatrix(!1,!0),e.dispatchEvent(sh),Ni.child=e,this.dispatchEvent(Ni),Ni.child=null,this}getObjectById(e){return this.getObjectByProperty("id",e)}getObjectByName(e){return this.getObjectByProperty("name",e)}getObjectByProperty(e,t){if(this[e]===t)return this;for(let n=0,r=this.children.length;n<r;n++){let a=this.children[n].getObjectByProperty(e,t);if(a!==void 0)return a}}getObjectsByProperty(e,t,n=[]){this[e]===t&&n.push(this);let r=this.children;for(let s=0,a=r.length;s<a;s++)r[s].getObjectsByProperty(e,t,n);return n}getWorldPosition(e){return this.updateWorldMatrix(!0,!1),e.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(xr,e,ip),e}getWorldScale(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(xr,rp,e),e}getWorldDirection(e){this.updateWorldMatrix(!0,!1);let t=this.matrixWorld.elements;return e.set(t[8],t[9],t[10]).normalize()}raycast(){}traverse(e){e(this);let t=this.children;for(let n=0,r=t.length;n<r;n++)t[n].traverse(e)}traverseVisible(e){if(this.visible===!1)return;e(this);let t=this.children;for(let n=0,r=t.length;n<r;n++)t[n].traverseVisible(e)}traverseAncestors(e){let t=this.parent;t!==null&&(e(t),t.traverseAncestors(e))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale),this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(e){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||e)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,e=!0);let t=this.children;for(let n=0,r=t.length;n<r;n++)t[n].updateMatrixWorld(e)}updateWorldMatrix(e,t){let n=this.parent;if(e===!0&&n!==null&&n.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),t===!0){let r=this.children;for(let s=0,a=r.length;s<a;s++)r[s].updateWorldMatrix(!1,!0)}}toJSON(e){let t=e===void 0||typeof e=="string",n={};t&&(e={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},n.metadata={version:4.6,type:"Object",generator:"Object3D.toJSON"});let r={};r.uuid=this.uuid,r.type=this.type,this.name!==""&&(r.name=this.name),this.castShadow===!0&&(r.castShadow=!0),this.receiveShadow===!0&&(r.receiveShadow=!0),this.visible===!1&&(r.visible=!1),this.frustumCulled===!1&&(r.frustumCulled=!1),this.renderOrder!==0&&(r.renderOrder=this.renderOrder),Object.keys(this.userData).length>0&&(r.userData=this.userData),r.layers=this.layers.mask,r.matrix=this.matrix.toArray(),r.up=this.up.toArray(),this.matrixAutoUpdate===!1&&(r.matrixAutoUpdate=!1),this.isInstancedMesh&&(r.type="InstancedMesh",r.count=this.count,r.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(r.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(r.type="BatchedMesh",r.perObjectFrustumCulled=this.perObjectFrustumCulled,r.sortObjects=this.sortObjects,r.drawRanges=this._drawRanges,r.reservedRanges=this._reservedRanges,r.visibility=this._visibility,r.active=this._active,r.bounds=this._bounds.map(o=>({boxInitialized:o.boxInitialized,boxMin:o.box.min.toArray(),boxMax:o.box.max.toArray(),sphereInitialized:o.sphereInitialized,sphereRadius:o.sphere.radius,sphereCenter:o.sphere.center.toArray()})),r.maxInstanceCount=this._maxInstanceCount,r.maxVertexCount=this._maxVertexCount,r.maxIndexCount=this._maxIndexCount,r.geometryInitialized=this._geometryInitialized,r.geometryCount=this._geometryCount,r.matricesTexture=this._matricesTexture.toJSON(e),this._colorsTexture!==null&&(r.colorsTexture=this._colorsTexture.toJSON(e)),this.boundingSphere!==null&&(r.boundingSphere={center:r.boundingSphere.center.toArray(),radius:r.boundingSphere.radius}),this.boundingBox!==null&&(r.boundingBox={min:r.boundingBox.min.toArray(),max:r.boundingBox.max.toArray()}));function s(o,l){return o[l.uuid]===void 0&&(o[l.uuid]=l.toJSON(e)),l.uuid}if(this.isScene)this.background&&(this.background.isColor?r.background=this.background.toJSON():this.background.isTexture&&(r.background=this.background.toJSON(e).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(r.environment=this.environment.toJSON(e).uuid);else if(this.isMesh||this.isLine||this.isPoints){r.geometry=s(e.geometries,this.geometry);let o=this.geometry.parameters;if(o!==void 0&&o.shapes!==void 0){let l=o.shapes;if(Array.isArray(l))for(let h=0,d=l.length;h<d;h++){let m=l[h];s(e.shapes,m)}else s(e.shapes,l)}}if(this.isSkinnedMesh&&(r.bindMode=this.bindMode,r.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(s(e.skeletons,this.skeleton),r.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){let o=[];for(let l=0,h=this.material.length;l<h;l++)o.push(s(e.materials,this.material[l]));r.material=o}else r.material=s(e.materials,this.material);if(this.children.length>0){r.children=[];for(let o=0;o<this.children.length;o++)r.children.push(this.children[o].toJSON(e).object)}if(this.animations.length>0){r.animations=[];for(let o=0;o<this.animations.length;o++){let l=this.animations[o];r.animations.push(s(e.animations,l))}}if(t){let o=a(e.geometries),l=a(e.materials),h=a(e.textures),d=a(e.images),m=a(e.shapes),f=a(e.skeletons),v=a(e.animations),S=a(e.nodes);o.length>0&&(n.geometries=o),l.length>0&&(n.materials=l),h.length>0&&(n.textures=h),d.length>0&&(n.images=d),m.length>0&&(n.shapes=m),f.length>0&&(n.skeletons=f),v.length>0&&(n.animations=v),S.length>0&&(n.nodes=S)}return n.object=r,n;function a(o){let l=[];for(let h in o){let d=o[h];delete d.metadata,l.push(d)}return l}}clone(e){return new this.constructor().copy(this,e)}copy(e,t=!0){if(this.name=e.name,this.up.copy(e.up),this.position.copy(e.position),this.rotation.order=e.rotation.order,this.quaternion.copy(e.quaternion),this.scale.copy(e.scale),this.matrix.copy(e.matrix),this.matrixWorld.copy(e.matrixWorld),this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrixWorldAutoUpdate=e.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=e.matrixWorldNeedsUpdate,this.layers.mask=e.layers.mask,this.visible=e.visible,this.castShadow=e.castShadow,this.receiveShadow=e.receiveShadow,this.frustumCulled=e.frustumCulled,this.renderOrder=e.renderOrder,this.animations=e.animations.slice(),this.userData=JSON.parse(JSON.stringify(e.userData)),t===!0)for(let n=0;n<e.children.length;n++){let r=e.children[n];this.add(r.clone())}return this}};Kt.DEFAULT_UP=new X(0,1,0);Kt.DEFAULT_MATRIX_AUTO_UPDATE=!0;Kt.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;var nn=new X,Sn=new X,Ia=new X,Mn=new X,Ui=new X,Fi=new X,ah=new X,Da=new X,Na=new X,Ua=new X,Fa=new gt,Oa=new gt,ka=new gt,ui=class i{constructor(e=new X,t=new X,n=new X){this.a=e,this.b=t,this.c=n}static getNormal(e,t,n,r){r.subVectors(n,t),nn.subVectors(e,t),r.cross(nn);let s=r.lengthSq();return s>0?r.multiplyScalar(1/Math.sqrt(s)):r.set(0,0,0)}static getBarycoord(e,t,n,r,s){nn.subVectors(r,t),Sn.subVectors(n,t),Ia.subVectors(e,t);let a=nn.dot(nn),o=nn.dot(Sn),l=nn.dot(Ia),h=Sn.dot(Sn),d=Sn.dot(Ia),m=a*h-o*o;if(m===0)return s.set(0,0,0),null;let f=1/m,v=(h*l-o*d)*f,S=(a*d-o*l)*f;return s.set(1-v-S,S,v)}static containsPoint(e,t,n,r){return this.getBarycoord(e,t,n,r,Mn)===null?!1:Mn.x>=0&&Mn.y>=0&&Mn.x+Mn.y<=1}static getInterpolation(e,t,n,r,s,a,o,l){return this.getBarycoord(e,t,n,r,Mn)===null?(l.x=0,l.y=0,"z"in l&&(l.z=0),"w"in l&&(l.w=0),null):(l.setScalar(0),l.addScaledVector(s,Mn.x),l.addScaledVector(a,Mn.y),l.addScaledVector(o,Mn.z),l)}static getInterpolatedAttribute(e,t,n,r,s,a){return Fa.setScalar(0),Oa.setScalar(0),ka.setScalar(0),Fa.fromBufferAttribute(e,t),Oa.fromBufferAttribute(e,n),ka.fromBufferAttribute(e,r),a.setScalar(0),a.addScaledVector(Fa,s.x),a.addScaledVector(Oa,s.y),a.addScaledVector(ka,s.z),a}static isFrontFacing(e,t,n,r){return nn.subVectors(n,t),Sn.subVectors(e,t),nn.cross(Sn).dot(r)<0}set(e,t,n){return this.a.copy(e),this.b.copy(t),this.c.copy(n),this}setFromPointsAndIndices(e,t,n,r){return this.a.copy(e[t]),this.b.copy(e[n]),this.c.copy(e[r]),this}setFromAttributeAndIndices(e,t,n,r){return this.a.fromBufferAttribute(e,t),this.b.fromBufferAttribute(e,n),this.c.fromBufferAttribute(e,r),this}clone(){return new this.constructor().copy(this)}copy(e){return this.a.copy(e.a),this.b.copy(e.b),this.c.copy(e.c),this}getArea(){return nn.subVectors(this.c,this.b),Sn.subVectors(this.a,this.b),nn.cross(Sn).length()*.5}getMidpoint(e){return e.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(e){return i.getNormal(this.a,this.b,this.c,e)}getPlane(e){return e.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(e,t){return i.getBarycoord(e,this.a,this.b,this.c,t)}getInterpolation(e,t,n,r,s){return i.getInterpolation(e,this.a,this.b,this.c,t,n,r,s)}containsPoint(e){return i.containsPoint(e,this.a,this.b,this.c)}isFrontFacing(e){return i.isFrontFacing(this.a,this.b,this.c,e)}intersectsBox(e){return e.intersectsTriangle(this)}closestPointToPoint(e,t){let n=this.a,r=this.b,s=this.c,a,o;Ui.subVectors(r,n),Fi.subVectors(s,n),Da.subVectors(e,n);let l=Ui.dot(Da),h=Fi.dot(Da);if(l<=0&&h<=0)return t.copy(n);Na.subVectors(e,r);let d=Ui.dot(Na),m=Fi.dot(Na);if(d>=0&&m<=d)return t.copy(r);let f=l*m-d*h;if(f<=0&&l>=0&&d<=0)return a=l/(l-d),t.copy(n).addScaledVector(Ui,a);Ua.subVectors(e,s);let v=Ui.dot(Ua),S=Fi.dot(Ua);if(S>=0&&v<=S)return t.copy(s);let E=v*h-l*S;if(E<=0&&h>=0&&S<=0)return o=h/(h-S),t.copy(n).addScaledVector(Fi,o);let _=d*S-v*m;if(_<=0&&m-d>=0&&v-S>=0)return ah.subVectors(s,r),o=(m-d)/(m-d+(v-S)),t.copy(r).addScaledVector(ah,o);let g=1/(_+E+f);return a=E*g,o=f*g,t.copy(n).addScaledVector(Ui,a).addScaledVector(Fi,o)}equals(e){return e.a.equals(this.a)&&e.b.equals(this.b)&&e.c.equals(this.c)}},eu={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},Xn={h:0,s:0,l:0},ns={h:0,s:0,l:0};function Ba(i,e,t){return t<0&&(t+=1),t>1&&(t-=1),t<1/6?i+(e-i)*6*t:t<1/2?e:t<2/3?i+(e-i)*6*(2/3-t):i}var tt=class{constructor(e,t,n){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(e,t,n)}set(e,t,n){if(t===void 0&&n===void 0){let r=e;r&&r.isColor?this.copy(r):typeof r=="number"?this.setHex(r):typeof r=="string"&&this.setStyle(r)}else this.setRGB(e,t,n);return this}setScalar(e){return this.r=e,this.g=e,this.b=e,this}setHex(e,t=Yt){return e=Math.floor(e),this.r=(e>>16&255)/255,this.g=(e>>8&255)/255,this.b=(e&255)/255,et.toWorkingColorSpace(this,t),this}setRGB(e,t,n,r=et.workingColorSpace){return this.r=e,this.g=t,this.b=n,et.toWorkingColorSpace(this,r),this}setHSL(e,t,n,r=et.workingColorSpace){if(e=vc(e,1),t=Rt(t,0,1),n=Rt(n,0,1),t===0)this.r=this.g=this.b=n;else{let s=n<=.5?n*(1+t):n+t-n*t,a=2*n-s;this.r=Ba(a,s,e+1/3),this.g=Ba(a,s,e),this.b=Ba(a,s,e-1/3)}return et.toWorkingColorSpace(this,r),this}setStyle(e,t=Yt){function n(s){s!==void 0&&parseFloat(s)<1&&console.warn("THREE.Color: Alpha component of "+e+" will be ignored.")}let r;if(r=/^(\w+)\(([^\)]*)\)/.exec(e)){let s,a=r[1],o=r[2];switch(a){case"rgb":case"rgba":if(s=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d*\.?\d+)\s*)?$/.exec(o))return n(s[4]),this.setRGB(Math.min(255,parseInt(s[1],10))/255,Math.min(255,parseInt(s[2],10))/255,Math.min(255,parseInt(s[3],10))/255,t);if(s=/^\s*(\d+)\%\s*,\s*(\d+)\%\s*,\s*(\d+)\%\s*(?:,\s*(\d*\.?\d+)\s*)?$/.exec(o))return n(s[4]),this.setRGB(Math.min(100,parseInt(s[1],10))/100,Math.min(100,parseInt(s[2],10))/100,Math.min(100,parseInt(s[3],10))/100,t);break;case"hsl":case"hsla":if(s=/^\s*(\d*\.?\d+)\s*,\s*(\d*\.?\d+)\%\s*,\s*(\d*\.?\d+)\%\s*(?:,\s*(\d*\.?\d+)\s*)?$/.exec(o))return n(s[4]),this.setHSL(parseFloat(s[1])/360,parseFloat(s[2])/100,parseFloat(s[3])/100,t);break;default:console.warn("THREE.Color: Unknown color model "+e)}}else if(r=/^\#([A-Fa-f\d]+)$/.exec(e)){let s=r[1],a=s.length;if(a===3)return this.setRGB(parseInt(s.charAt(0),16)/15,parseInt(s.charAt(1),16)/15,parseInt(s.charAt(2),16)/15,t);if(a===6)return this.setHex(parseInt(s,16),t);console.warn("THREE.Color: Invalid hex color "+e)}else if(e&&e.length>0)return this.setColorName(e,t);return this}setColorName(e,t=Yt){let n=eu[e.toLowerCase()];return n!==void 0?this.setHex(n,t):console.warn("THREE.Color: Unknown color "+e),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(e){return this.r=e.r,this.g=e.g,this.b=e.b,this}copySRGBToLinear(e){return this.r=Cn(e.r),this.g=Cn(e.g),this.b=Cn(e.b),this}copyLinearToSRGB(e){return this.r=qi(e.r),this.g=qi(e.g),this.b=qi(e.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(e=Yt){return et.fromWorkingColorSpace(Ct.copy(this),e),Math.round(Rt(Ct.r*255,0,255))*65536+Math.round(Rt(Ct.g*255,0,255))*256+Math.round(Rt(Ct.b*255,0,255))}getHexString(e=Yt){return("000000"+this.getHex(e).toString(16)).slice(-6)}getHSL(e,t=et.workingColorSpace){et.fromWorkingColorSpace(Ct.copy(this),t);let n=Ct.r,r=Ct.g,s=Ct.b,a=Math.max(n,r,s),o=Math.min(n,r,s),l,h,d=(o+a)/2;if(o===a)l=0,h=0;else{let m=a-o;switch(h=d<=.5?m/(a+o):m/(2-a-o),a){case n:l=(r-s)/m+(r<s?6:0);break;case r:l=(s-n)/m+2;break;case s:l=(n-r)/m+4;break}l/=6}return e.h=l,e.s=h,e.l=d,e}getRGB(e,t=et.workingColorSpace){return et.fromWorkingColorSpace(Ct.copy(this),t),e.r=Ct.r,e.g=Ct.g,e.b=Ct.b,e}getStyle(e=Yt){et.fromWorkingColorSpace(Ct.copy(this),e);let t=Ct.r,n=Ct.g,r=Ct.b;return e!==Yt?`color(${e} ${t.toFixed(3)} ${n.toFixed(3)} ${r.toFixed(3)})`:`rgb(${Math.round(t*255)},${Math.round(n*255)},${Math.round(r*255)})`}offsetHSL(e,t,n){return this.getHSL(Xn),this.setHSL(Xn.h+e,Xn.s+t,Xn.l+n)}add(e){return this.r+=e.r,this.g+=e.g,this.b+=e.b,this}addColors(e,t){return this.r=e.r+t.r,this.g=e.g+t.g,this.b=e.b+t.b,this}addScalar(e){return this.r+=e,this.g+=e,this.b+=e,this}sub(e){return this.r=Math.max(0,this.r-e.r),this.g=Math.max(0,this.g-e.g),this.b=Math.max(0,this.b-e.b),this}multiply(e){return this.r*=e.r,this.g*=e.g,this.b*=e.b,this}multiplyScalar(e){return this.r*=e,this.g*=e,this.b*=e,this}lerp(e,t){return this.r+=(e.r-this.r)*t,this.g+=(e.g-this.g)*t,this.b+=(e.b-this.b)*t,this}lerpColors(e,t,n){return this.r=e.r+(t.r-e.r)*n,this.g=e.g+(t.g-e.g)*n,this.b=e.b+(t.b-e.b)*n,this}lerpHSL(e,t){this.getHSL(Xn),e.getHSL(ns);let n=Er(Xn.h,ns.h,t),r=Er(Xn.s,ns.s,t),s=Er(Xn.l,ns.l,t);return this.setHSL(n,r,s),this}setFromVector3(e){return this.r=e.x,this.g=e.y,this.b=e.z,this}applyMatrix3(e){let t=this.r,n=this.g,r=this.b,s=e.elements;return this.r=s[0]*t+s[3]*n+s[6]*r,this.g=s[1]*t+s[4]*n+s[7]*r,this.b=s[2]*t+s[5]*n+s[8]*r,this}equals(e){return e.r===this.r&&e.g===this.g&&e.b===this.b}fromArray(e,t=0){return this.r=e[t],this.g=e[t+1],this.b=e[t+2],this}toArray(e=[],t=0){return e[t]=this.r,e[t+1]=this.g,e[t+2]=this.b,e}fromBufferAttribute(e,t){return this.r=e.getX(t),this.g=e.getY(t),this.b=e.getZ(t),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}},Ct=new tt;tt.NAMES=eu;var ap=0,gi=class extends Pn{static get type(){return"Material"}get type(){return this.constructor.type}set type(e){}constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:ap++}),this.uuid=rr(),this.name="",this.blending=Wi,this.side=Kn,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=$a,this.blendDst=Ka,this.blendEquation=hi,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new tt(0,0,0),this.blendAlpha=0,this.depthFunc=Zi,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=Vl,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=Ai,this.stencilZFail=Ai,this.stencilZPass=Ai,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(e){this._alphaTest>0!=e>0&&this.version++,this._alphaTest=e}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(e){if(e!==void 0)for(let t in e){let n=e[t];if(n===void 0){console.warn(`THREE.Material: parameter '${t}' has value of undefined.`);continue}let r=this[t];if(r===void 0){console.warn(`THREE.Material: '${t}' is not a property of THREE.${this.type}.`);continue}r&&r.isColor?r.set(n):r&&r.isVector3&&n&&n.isVector3?r.copy(n):this[t]=n}}toJSON(e){let t=e===void 0||typeof e=="string";t&&(e={textures:{},images:{}});let n={metadata:{version:4.6,type:"Material",generator:"Material.toJSON"}};n.uuid=this.uuid,n.type=this.type,this.name!==""&&(n.name=this.name),this.color&&this.color.isColor&&(n.color=this.color.getHex()),this.roughness!==void 0&&(n.roughness=this.roughness),this.metalness!==void 0&&(n.metalness=this.metalness),this.sheen!==void 0&&(n.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(n.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(n.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(n.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&this.emissiveIntensity!==1&&(n.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(n.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(n.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(n.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(n.shininess=this.shininess),this.clearcoat!==void 0&&(n.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(n.clearcoatRoughness=this.clearcoatRoughness),this.clearcoatMap&&this.clearcoatMap.isTexture&&(n.clearcoatMap=this.clearcoatMap.toJSON(e).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(n.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(e).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(n.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(e).uuid,n.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.dispersion!==void 0&&(n.dispersion=this.dispersion),this.iridescence!==void 0&&(n.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(n.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessRange!==void 0&&(n.iridescenceThicknessRange=this.iridescenceThicknessRange),this.iridescenceMap&&this.iridescenceMap.isTexture&&(n.iridescenceMap=this.iridescenceMap.toJSON(e).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(n.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(e).uuid),this.anisotropy!==void 0&&(n.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(n.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(n.anisotropyMap=this.anisotropyMap.toJSON(e).uuid),this.map&&this.map.isTexture&&(n.map=this.map.toJSON(e).uuid),this.matcap&&this.matcap.isTexture&&(n.matcap=this.matcap.toJSON(e).uuid),this.alphaMap&&this.alphaMap.isTexture&&(n.alphaMap=this.alphaMap.toJSON(e).uuid),this.lightMap&&this.lightMap.isTexture&&(n.lightMap=this.lightMap.toJSON(e).uuid,n.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(n.aoMap=this.aoMap.toJSON(e).uuid,n.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(n.bumpMap=this.bumpMap.toJSON(e).uuid,n.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(n.normalMap=this.normalMap.toJSON(e).uuid,n.normalMapType=this.normalMapType,n.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(n.displacementMap=this.displacementMap.toJSON(e).uuid,n.displacementScale=this.displacementScale,n.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(n.roughnessMap=this.roughnessMap.toJSON(e).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(n.metalnessMap=this.metalnessMap.toJSON(e).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(n.emissiveMap=this.emissiveMap.toJSON(e).uuid),this.specularMap&&this.specularMap.isTexture&&(n.specularMap=this.specularMap.toJSON(e).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(n.specularIntensityMap=this.specularIntensityMap.toJSON(e).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(n.specularColorMap=this.specularColorMap.toJSON(e).uuid),this.envMap&&this.envMap.isTexture&&(n.envMap=this.envMap.toJSON(e).uuid,this.combine!==void 0&&(n.combine=this.combine)),this.envMapRotation!==void 0&&(n.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(n.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(n.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(n.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(n.gradientMap=this.gradientMap.toJSON(e).uuid),this.transmission!==void 0&&(n.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(n.transmissionMap=this.transmissionMap.toJSON(e).uuid),this.thickness!==void 0&&(n.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(n.thicknessMap=this.thicknessMap.toJSON(e).uuid),this.attenuationDistance!==void 0&&this.attenuationDistance!==1/0&&(n.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(n.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(n.size=this.size),this.shadowSide!==null&&(n.shadowSide=this.shadowSide),this.sizeAttenuation!==void 0&&(n.sizeAttenuation=this.sizeAttenuation),this.blending!==Wi&&(n.blending=this.blending),this.side!==Kn&&(n.side=this.side),this.vertexColors===!0&&(n.vertexColors=!0),this.opacity<1&&(n.opacity=this.opacity),this.transparent===!0&&(n.transparent=!0),this.blendSrc!==$a&&(n.blendSrc=this.blendSrc),this.blendDst!==Ka&&(n.blendDst=this.blendDst),this.blendEquation!==hi&&(n.blendEquation=this.blendEquation),this.blendSrcAlpha!==null&&(n.blendSrcAlpha=this.blendSrcAlpha),this.blendDstAlpha!==null&&(n.blendDstAlpha=this.blendDstAlpha),this.blendEquationAlpha!==null&&(n.blendEquationAlpha=this.blendEquationAlpha),this.blendColor&&this.blendColor.isColor&&(n.blendColor=this.blendColor.getHex()),this.blendAlpha!==0&&(n.blendAlpha=this.blendAlpha),this.depthFunc!==Zi&&(n.depthFunc=this.depthFunc),this.depthTest===!1&&(n.depthTest=this.depthTest),this.depthWrite===!1&&(n.depthWrite=this.depthWrite),this.colorWrite===!1&&(n.colorWrite=this.colorWrite),this.stencilWriteMask!==255&&(n.stencilWriteMask=this.stencilWriteMask),this.stencilFunc!==Vl&&(n.stencilFunc=this.stencilFunc),this.stencilRef!==0&&(n.stencilRef=this.stencilRef),this.stencilFuncMask!==255&&(n.stencilFuncMask=this.stencilFuncMask),this.stencilFail!==Ai&&(n.stencilFail=this.stencilFail),this.stencilZFail!==Ai&&(n.stencilZFail=this.stencilZFail),this.stencilZPass!==Ai&&(n.stencilZPass=this.stencilZPass),this.stencilWrite===!0&&(n.stencilWrite=this.stencilWrite),this.rotation!==void 0&&this.rotation!==0&&(n.rotation=this.rotation),this.polygonOffset===!0&&(n.polygonOffset=!0),this.polygonOffsetFactor!==0&&(n.polygonOffsetFactor=this.polygonOffsetFactor),this.polygonOffsetUnits!==0&&(n.polygonOffsetUnits=this.polygonOffsetUnits),this.linewidth!==void 0&&this.linewidth!==1&&(n.linewidth=this.linewidth),this.dashSize!==void 0&&(n.dashSize=this.dashSize),this.gapSize!==void 0&&(n.gapSize=this.gapSize),this.scale!==void 0&&(n.scale=this.scale),this.dithering===!0&&(n.dithering=!0),this.alphaTest>0&&(n.alphaTest=this.alphaTest),this.alphaHash===!0&&(n.alphaHash=!0),this.alphaToCoverage===!0&&(n.alphaToCoverage=!0),this.premultipliedAlpha===!0&&(n.premultipliedAlpha=!0),this.forceSinglePass===!0&&(n.forceSinglePass=!0),this.wireframe===!0&&(n.wireframe=!0),this.wireframeLinewidth>1&&(n.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!=="round"&&(n.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!=="round"&&(n.wireframeLinejoin=this.wireframeLinejoin),this.flatShading===!0&&(n.flatShading=!0),this.visible===!1&&(n.visible=!1),this.toneMapped===!1&&(n.toneMapped=!1),this.fog===!1&&(n.fog=!1),Object.keys(this.userData).length>0&&(n.userData=this.userData);function r(s){let a=[];for(let o in s){let l=s[o];delete l.metadata,a.push(l)}return a}if(t){let s=r(e.textures),a=r(e.images);s.length>0&&(n.textures=s),a.length>0&&(n.images=a)}return n}clone(){return new this.constructor().copy(this)}copy(e){this.name=e.name,this.blending=e.blending,this.side=e.side,this.vertexColors=e.vertexColors,this.opacity=e.opacity,this.transparent=e.transparent,this.blendSrc=e.blendSrc,this.blendDst=e.blendDst,this.blendEquation=e.blendEquation,this.blendSrcAlpha=e.blendSrcAlpha,this.blendDstAlpha=e.blendDstAlpha,this.blendEquationAlpha=e.blendEquationAlpha,this.blendColor.copy(e.blendColor),this.blendAlpha=e.blendAlpha,this.depthFunc=e.depthFunc,this.depthTest=e.depthTest,this.depthWrite=e.depthWrite,this.stencilWriteMask=e.stencilWriteMask,this.stencilFunc=e.stencilFunc,this.stencilRef=e.stencilRef,this.stencilFuncMask=e.stencilFuncMask,this.stencilFail=e.stencilFail,this.stencilZFail=e.stencilZFail,this.stencilZPass=e.stencilZPass,this.stencilWrite=e.stencilWrite;let t=e.clippingPlanes,n=null;if(t!==null){let r=t.length;n=new Array(r);for(let s=0;s!==r;++s)n[s]=t[s].clone()}return this.clippingPlanes=n,this.clipIntersection=e.clipIntersection,this.clipShadows=e.clipShadows,this.shadowSide=e.shadowSide,this.colorWrite=e.colorWrite,this.precision=e.precision,this.polygonOffset=e.polygonOffset,this.polygonOffsetFactor=e.polygonOffsetFactor,this.polygonOffsetUnits=e.polygonOffsetUnits,this.dithering=e.dithering,this.alphaTest=e.alphaTest,this.alphaHash=e.alphaHash,this.alphaToCoverage=e.alphaToCoverage,this.premultipliedAlpha=e.premultipliedAlpha,this.forceSinglePass=e.forceSinglePass,this.visible=e.visible,this.toneMapped=e.toneMapped,this.userData=JSON.parse(JSON.stringify(e.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(e){e===!0&&this.version++}onBuild(){console.warn("Material: onBuild() has been removed.")}},Rs=class extends gi{static get type(){return"MeshBasicMaterial"}constructor(e){super(),this.isMeshBasicMaterial=!0,this.color=new tt(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Dn,this.combine=Bh,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.specularMap=e.specularMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.combine=e.combine,this.reflectivity=e.reflectivity,this.refractionRatio=e.refractionRatio,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.fog=e.fog,this}};var vt=new X,is=new $e,Zt=class{constructor(e,t,n=!1){if(Array.isArray(e))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,this.name="",this.array=e,this.itemSize=t,this.count=e!==void 0?e.length/t:0,this.normalized=n,this.usage=Hl,this.updateRanges=[],this.gpuType=Tn,this.version=0}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.name=e.name,this.array=new e.array.constructor(e.array),this.itemSize=e.itemSize,this.count=e.count,this.normalized=e.normalized,this.usage=e.usage,this.gpuType=e.gpuType,this}copyAt(e,t,n){e*=this.itemSize,n*=t.itemSize;for(let r=0,s=this.itemSize;r<s;r++)this.array[e+r]=t.array[n+r];return this}copyArray(e){return this.array.set(e),this}applyMatrix3(e){if(this.itemSize===2)for(let t=0,n=this.count;t<n;t++)is.fromBufferAttribute(this,t),is.applyMatrix3(e),this.setXY(t,is.x,is.y);else if(this.itemSize===3)for(let t=0,n=this.count;t<n;t++)vt.fromBufferAttribute(this,t),vt.applyMatrix3(e),this.setXYZ(t,vt.x,vt.y,vt.z);return this}applyMatrix4(e){for(let t=0,n=this.count;t<n;t++)vt.fromBufferAttribute(this,t),vt.applyMatrix4(e),this.setXYZ(t,vt.x,vt.y,vt.z);return this}applyNormalMatrix(e){for(let t=0,n=this.count;t<n;t++)vt.fromBufferAttribute(this,t),vt.applyNormalMatrix(e),this.setXYZ(t,vt.x,vt.y,vt.z);return this}transformDirection(e){for(let t=0,n=this.count;t<n;t++)vt.fromBufferAttribute(this,t),vt.transformDirection(e),this.setXYZ(t,vt.x,vt.y,vt.z);return this}set(e,t=0){return this.array.set(e,t),this}getComponent(e,t){let n=this.array[e*this.itemSize+t];return this.normalized&&(n=Gi(n,this.array)),n}setComponent(e,t,n){return this.normalized&&(n=It(n,this.array)),this.array[e*this.itemSize+t]=n,this}getX(e){let t=this.array[e*this.itemSize];return this.normalized&&(t=Gi(t,this.array)),t}setX(e,t){return this.normalized&&(t=It(t,this.array)),this.array[e*this.itemSize]=t,this}getY(e){let t=this.array[e*this.itemSize+1];return this.normalized&&(t=Gi(t,this.array)),t}setY(e,t){return this.normalized&&(t=It(t,this.array)),this.array[e*this.itemSize+1]=t,this}getZ(e){let t=this.array[e*this.itemSize+2];return this.normalized&&(t=Gi(t,this.array)),t}setZ(e,t){return this.normalized&&(t=It(t,this.array)),this.array[e*this.itemSize+2]=t,this}getW(e){let t=this.array[e*this.itemSize+3];return this.normalized&&(t=Gi(t,this.array)),t}setW(e,t){return this.normalized&&(t=It(t,this.array)),this.array[e*this.itemSize+3]=t,this}setXY(e,t,n){return e*=this.itemSize,this.normalized&&(t=It(t,this.array),n=It(n,this.array)),this.array[e+0]=t,this.array[e+1]=n,this}setXYZ(e,t,n,r){return e*=this.itemSize,this.normalized&&(t=It(t,this.array),n=It(n,this.array),r=It(r,this.array)),this.array[e+0]=t,this.array[e+1]=n,this.array[e+2]=r,this}setXYZW(e,t,n,r,s){return e*=this.itemSize,this.normalized&&(t=It(t,this.array),n=It(n,this.array),r=It(r,this.array),s=It(s,this.array)),this.array[e+0]=t,this.array[e+1]=n,this.array[e+2]=r,this.array[e+3]=s,this}onUpload(e){return this.onUploadCallback=e,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){let e={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return this.name!==""&&(e.name=this.name),this.usage!==Hl&&(e.usage=this.usage),e}};var Ps=class extends Zt{constructor(e,t,n){super(new Uint16Array(e),t,n)}};var Ls=class extends Zt{constructor(e,t,n){super(new Uint32Array(e),t,n)}};var cn=class extends Zt{constructor(e,t,n){super(new Float32Array(e),t,n)}},op=0,qt=new _t,za=new Kt,Oi=new X,Vt=new In,br=new In,Et=new X,pn=class i extends Pn{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:op++}),this.uuid=rr(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={}}getIndex(){return this.index}setIndex(e){return Array.isArray(e)?this.index=new(Qh(e)?Ls:Ps)(e,1):this.index=e,this}setIndirect(e){return this.indirect=e,this}getIndirect(){return this.indirect}getAttribute(e){return this.attributes[e]}setAttribute(e,t){return this.attributes[e]=t,this}deleteAttribute(e){return delete this.attributes[e],this}hasAttribute(e){return this.attributes[e]!==void 0}addGroup(e,t,n=0){this.groups.push({start:e,count:t,materialIndex:n})}clearGroups(){this.groups=[]}setDrawRange(e,t){this.drawRange.start=e,this.drawRange.count=t}applyMatrix4(e){let t=this.attributes.position;t!==void 0&&(t.applyMatrix4(e),t.needsUpdate=!0);let n=this.attributes.normal;if(n!==void 0){let s=new He().getNormalMatrix(e);n.applyNormalMatrix(s),n.needsUpdate=!0}let r=this.attributes.tangent;return r!==void 0&&(r.transformDirection(e),r.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this}applyQuaternion(e){return qt.makeRotationFromQuaternion(e),this.applyMatrix4(qt),this}rotateX(e){return qt.makeRotationX(e),this.applyMatrix4(qt),this}rotateY(e){return qt.makeRotationY(e),this.applyMatrix4(qt),this}rotateZ(e){return qt.makeRotationZ(e),this.applyMatrix4(qt),this}translate(e,t,n){return qt.makeTranslation(e,t,n),this.applyMatrix4(qt),this}scale(e,t,n){return qt.makeScale(e,t,n),this.applyMatrix4(qt),this}lookAt(e){return za.lookAt(e),za.updateMatrix(),this.applyMatrix4(za.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(Oi).negate(),this.translate(Oi.x,Oi.y,Oi.z),this}setFromPoints(e){let t=this.getAttribute("position");if(t===void 0){let n=[];for(let r=0,s=e.length;r<s;r++){let a=e[r];n.push(a.x,a.y,a.z||0)}this.setAttribute("position",new cn(n,3))}else{for(let n=0,r=t.count;n<r;n++){let s=e[n];t.setXYZ(n,s.x,s.y,s.z||0)}e.length>t.count&&console.warn("THREE.BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),t.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new In);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){console.error("THREE.BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new X(-1/0,-1/0,-1/0),new X(1/0,1/0,1/0));return}if(e!==void 0){if(this.boundingBox.setFromBufferAttribute(e),t)for(let n=0,r=t.length;n<r;n++){let s=t[n];Vt.setFromBufferAttribute(s),this.morphTargetsRelative?(Et.addVectors(this.boundingBox.min,Vt.min),this.boundingBox.expandByPoint(Et),Et.addVectors(this.boundingBox.max,Vt.max),this.boundingBox.expandByPoint(Et)):(this.boundingBox.expandByPoint(Vt.min),this.boundingBox.expandByPoint(Vt.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&console.error('THREE.BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new Qi);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){console.error("THREE.BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new X,1/0);return}if(e){let n=this.boundingSphere.center;if(Vt.setFromBufferAttribute(e),t)for(let s=0,a=t.length;s<a;s++){let o=t[s];br.setFromBufferAttribute(o),this.morphTargetsRelative?(Et.addVectors(Vt.min,br.min),Vt.expandByPoint(Et),Et.addVectors(Vt.max,br.max),Vt.expandByPoint(Et)):(Vt.expandByPoint(br.min),Vt.expandByPoint(br.max))}Vt.getCenter(n);let r=0;for(let s=0,a=e.count;s<a;s++)Et.fromBufferAttribute(e,s),r=Math.max(r,n.distanceToSquared(Et));if(t)for(let s=0,a=t.length;s<a;s++){let o=t[s],l=this.morphTargetsRelative;for(let h=0,d=o.count;h<d;h++)Et.fromBufferAttribute(o,h),l&&(Oi.fromBufferAttribute(e,h),Et.add(Oi)),r=Math.max(r,n.distanceToSquared(Et))}this.boundingSphere.radius=Math.sqrt(r),isNaN(this.boundingSphere.radius)&&console.error('THREE.BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){let e=this.index,t=this.attributes;if(e===null||t.position===void 0||t.normal===void 0||t.uv===void 0){console.error("THREE.BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}let n=t.position,r=t.normal,s=t.uv;this.hasAttribute("tangent")===!1&&this.setAttribute("tangent",new Zt(new Float32Array(4*n.count),4));let a=this.getAttribute("tangent"),o=[],l=[];for(let V=0;V<n.count;V++)o[V]=new X,l[V]=new X;let h=new X,d=new X,m=new X,f=new $e,v=new $e,S=new $e,E=new X,_=new X;function g(V,L,R){h.fromBufferAttribute(n,V),d.fromBufferAttribute(n,L),m.fromBufferAttribute(n,R),f.fromBufferAttribute(s,V),v.fromBufferAttribute(s,L),S.fromBufferAttribute(s,R),d.sub(h),m.sub(h),v.sub(f),S.sub(f);let F=1/(v.x*S.y-S.x*v.y);isFinite(F)&&(E.copy(d).multiplyScalar(S.y).addScaledVector(m,-v.y).multiplyScalar(F),_.copy(m).multiplyScalar(v.x).addScaledVector(d,-S.x).multiplyScalar(F),o[V].add(E),o[L].add(E),o[R].add(E),l[V].add(_),l[L].add(_),l[R].add(_))}let I=this.groups;I.length===0&&(I=[{start:0,count:e.count}]);for(let V=0,L=I.length;V<L;++V){let R=I[V],F=R.start,Q=R.count;for(let Z=F,J=F+Q;Z<J;Z+=3)g(e.getX(Z+0),e.getX(Z+1),e.getX(Z+2))}let P=new X,C=new X,H=new X,U=new X;function N(V){H.fromBufferAttribute(r,V),U.copy(H);let L=o[V];P.copy(L),P.sub(H.multiplyScalar(H.dot(L))).normalize(),C.crossVectors(U,L);let F=C.dot(l[V])<0?-1:1;a.setXYZW(V,P.x,P.y,P.z,F)}for(let V=0,L=I.length;V<L;++V){let R=I[V],F=R.start,Q=R.count;for(let Z=F,J=F+Q;Z<J;Z+=3)N(e.getX(Z+0)),N(e.getX(Z+1)),N(e.getX(Z+2))}}computeVertexNormals(){let e=this.index,t=this.getAttribute("position");if(t!==void 0){let n=this.getAttribute("normal");if(n===void 0)n=new Zt(new Float32Array(t.count*3),3),this.setAttribute("normal",n);else for(let f=0,v=n.count;f<v;f++)n.setXYZ(f,0,0,0);let r=new X,s=new X,a=new X,o=new X,l=new X,h=new X,d=new X,m=new X;if(e)for(let f=0,v=e.count;f<v;f+=3){let S=e.getX(f+0),E=e.getX(f+1),_=e.getX(f+2);r.fromBufferAttribute(t,S),s.fromBufferAttribute(t,E),a.fromBufferAttribute(t,_),d.subVectors(a,s),m.subVectors(r,s),d.cross(m),o.fromBufferAttribute(n,S),l.fromBufferAttribute(n,E),h.fromBufferAttribute(n,_),o.add(d),l.add(d),h.add(d),n.setXYZ(S,o.x,o.y,o.z),n.setXYZ(E,l.x,l.y,l.z),n.setXYZ(_,h.x,h.y,h.z)}else for(let f=0,v=t.count;f<v;f+=3)r.fromBufferAttribute(t,f+0),s.fromBufferAttribute(t,f+1),a.fromBufferAttribute(t,f+2),d.subVectors(a,s),m.subVectors(r,s),d.cross(m),n.setXYZ(f+0,d.x,d.y,d.z),n.setXYZ(f+1,d.x,d.y,d.z),n.setXYZ(f+2,d.x,d.y,d.z);this.normalizeNormals(),n.needsUpdate=!0}}normalizeNormals(){let e=this.attributes.normal;for(let t=0,n=e.count;t<n;t++)Et.fromBufferAttribute(e,t),Et.normalize(),e.setXYZ(t,Et.x,Et.y,Et.z)}toNonIndexed(){function e(o,l){let h=o.array,d=o.itemSize,m=o.normalized,f=new h.constructor(l.length*d),v=0,S=0;for(let E=0,_=l.length;E<_;E++){o.isInterleavedBufferAttribute?v=l[E]*o.data.stride+o.offset:v=l[E]*d;for(let g=0;g<d;g++)f[S++]=h[v++]}return new Zt(f,d,m)}if(this.index===null)return console.warn("THREE.BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;let t=new i,n=this.index.array,r=this.attributes;for(let o in r){let l=r[o],h=e(l,n);t.setAttribute(o,h)}let s=this.morphAttributes;for(let o in s){let l=[],h=s[o];for(let d=0,m=h.length;d<m;d++){let f=h[d],v=e(f,n);l.push(v)}t.morphAttributes[o]=l}t.morphTargetsRelative=this.morphTargetsRelative;let a=this.groups;for(let o=0,l=a.length;o<l;o++){let h=a[o];t.addGroup(h.start,h.count,h.materialIndex)}return t}toJSON(){let e={metadata:{version:4.6,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(e.uuid=this.uuid,e.type=this.type,this.name!==""&&(e.name=this.name),Object.keys(this.userData).length>0&&(e.userData=this.userData),this.parameters!==void 0){let l=this.parameters;for(let h in l)l[h]!==void 0&&(e[h]=l[h]);return e}e.data={attributes:{}};let t=this.index;t!==null&&(e.data.index={type:t.array.constructor.name,array:Array.prototype.slice.call(t.array)});let n=this.attributes;for(let l in n){let h=n[l];e.data.attributes[l]=h.toJSON(e.data)}let r={},s=!1;for(let l in this.morphAttributes){let h=this.morphAttributes[l],d=[];for(let m=0,f=h.length;m<f;m++){let v=h[m];d.push(v.toJSON(e.data))}d.length>0&&(r[l]=d,s=!0)}s&&(e.data.morphAttributes=r,e.data.morphTargetsRelative=this.morphTargetsRelative);let a=this.groups;a.length>0&&(e.data.groups=JSON.parse(JSON.stringify(a)));let o=this.boundingSphere;return o!==null&&(e.data.boundingSphere={center:o.center.toArray(),radius:o.radius}),e}clone(){return new this.constructor().copy(this)}copy(e){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;let t={};this.name=e.name;let n=e.index;n!==null&&this.setIndex(n.clone(t));let r=e.attributes;for(let h in r){let d=r[h];this.setAttribute(h,d.clone(t))}let s=e.morphAttributes;for(let h in s){let d=[],m=s[h];for(let f=0,v=m.length;f<v;f++)d.push(m[f].clone(t));this.morphAttributes[h]=d}this.morphTargetsRelative=e.morphTargetsRelative;let a=e.groups;for(let h=0,d=a.length;h<d;h++){let m=a[h];this.addGroup(m.start,m.count,m.materialIndex)}let o=e.boundingBox;o!==null&&(this.boundingBox=o.clone());let l=e.boundingSphere;return l!==null&&(this.boundingSphere=l.clone()),this.drawRange.start=e.drawRange.start,this.drawRange.count=e.drawRange.count,this.userData=e.userData,this}dispose(){this.dispatchEvent({type:"dispose"})}},oh=new _t,si=new er,rs=new Qi,ch=new X,ss=new X,as=new X,os=new X,Ga=new X,cs=new X,lh=new X,ls=new X,an=class extends Kt{constructor(e=new pn,t=new Rs){super(),this.isMesh=!0,this.type="Mesh",this.geometry=e,this.material=t,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0&&(this.morphTargetInfluences=e.morphTargetInfluences.slice()),e.morphTargetDictionary!==void 0&&(this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary)),this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}updateMorphTargets(){let t=this.geometry.morphAttributes,n=Object.keys(t);if(n.length>0){let r=t[n[0]];if(r!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let s=0,a=r.length;s<a;s++){let o=r[s].name||String(s);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=s}}}}getVertexPosition(e,t){let n=this.geometry,r=n.attributes.position,s=n.morphAttributes.position,a=n.morphTargetsRelative;t.fromBufferAttribute(r,e);let o=this.morphTargetInfluences;if(s&&o){cs.set(0,0,0);for(let l=0,h=s.length;l<h;l++){let d=o[l],m=s[l];d!==0&&(Ga.fromBufferAttribute(m,e),a?cs.addScaledVector(Ga,d):cs.addScaledVector(Ga.sub(t),d))}t.add(cs)}return t}raycast(e,t){let n=this.geometry,r=this.material,s=this.matrixWorld;r!==void 0&&(n.boundingSphere===null&&n.computeBoundingSphere(),rs.copy(n.boundingSphere),rs.applyMatrix4(s),si.copy(e.ray).recast(e.near),!(rs.containsPoint(si.origin)===!1&&(si.intersectSphere(rs,ch)===null||si.origin.distanceToSquared(ch)>(e.far-e.near)**2))&&(oh.copy(s).invert(),si.copy(e.ray).applyMatrix4(oh),!(n.boundingBox!==null&&si.intersectsBox(n.boundingBox)===!1)&&this._computeIntersections(e,t,si)))}_computeIntersections(e,t,n){let r,s=this.geometry,a=this.material,o=s.index,l=s.attributes.position,h=s.attributes.uv,d=s.attributes.uv1,m=s.attributes.normal,f=s.groups,v=s.drawRange;if(o!==null)if(Array.isArray(a))for(let S=0,E=f.length;S<E;S++){let _=f[S],g=a[_.materialIndex],I=Math.max(_.start,v.start),P=Math.min(o.count,Math.min(_.start+_.count,v.start+v.count));for(let C=I,H=P;C<H;C+=3){let U=o.getX(C),N=o.getX(C+1),V=o.getX(C+2);r=hs(this,g,e,n,h,d,m,U,N,V),r&&(r.faceIndex=Math.floor(C/3),r.face.materialIndex=_.materialIndex,t.push(r))}}else{let S=Math.max(0,v.start),E=Math.min(o.count,v.start+v.count);for(let _=S,g=E;_<g;_+=3){let I=o.getX(_),P=o.getX(_+1),C=o.getX(_+2);r=hs(this,a,e,n,h,d,m,I,P,C),r&&(r.faceIndex=Math.floor(_/3),t.push(r))}}else if(l!==void 0)if(Array.isArray(a))for(let S=0,E=f.length;S<E;S++){let _=f[S],g=a[_.materialIndex],I=Math.max(_.start,v.start),P=Math.min(l.count,Math.min(_.start+_.count,v.start+v.count));for(let C=I,H=P;C<H;C+=3){let U=C,N=C+1,V=C+2;r=hs(this,g,e,n,h,d,m,U,N,V),r&&(r.faceIndex=Math.floor(C/3),r.face.materialIndex=_.materialIndex,t.push(r))}}else{let S=Math.max(0,v.start),E=Math.min(l.count,v.start+v.count);for(let _=S,g=E;_<g;_+=3){let I=_,P=_+1,C=_+2;r=hs(this,a,e,n,h,d,m,I,P,C),r&&(r.faceIndex=Math.floor(_/3),t.push(r))}}}};function cp(i,e,t,n,r,s,a,o){let l;if(e.side===kt?l=n.intersectTriangle(a,s,r,!0,o):l=n.intersectTriangle(r,s,a,e.side===Kn,o),l===null)return null;ls.copy(o),ls.applyMatrix4(i.matrixWorld);let h=t.ray.origin.distanceTo(ls);return h<t.near||h>t.far?null:{distance:h,point:ls.clone(),object:i}}function hs(i,e,t,n,r,s,a,o,l,h){i.getVertexPosition(o,ss),i.getVertexPosition(l,as),i.getVertexPosition(h,os);let d=cp(i,e,t,n,ss,as,os,lh);if(d){let m=new X;ui.getBarycoord(lh,ss,as,os,m),r&&(d.uv=ui.getInterpolatedAttribute(r,o,l,h,m,new $e)),s&&(d.uv1=ui.getInterpolatedAttribute(s,o,l,h,m,new $e)),a&&(d.normal=ui.getInterpolatedAttribute(a,o,l,h,m,new X),d.normal.dot(n.direction)>0&&d.normal.multiplyScalar(-1));let f={a:o,b:l,c:h,normal:new X,materialIndex:0};ui.getNormal(ss,as,os,f.normal),d.face=f,d.barycoord=m}return d}var Rr=class i extends pn{constructor(e=1,t=1,n=1,r=1,s=1,a=1){super(),this.type="BoxGeometry",this.parameters={width:e,height:t,depth:n,widthSegments:r,heightSegments:s,depthSegments:a};let o=this;r=Math.floor(r),s=Math.floor(s),a=Math.floor(a);let l=[],h=[],d=[],m=[],f=0,v=0;S("z","y","x",-1,-1,n,t,e,a,s,0),S("z","y","x",1,-1,n,t,-e,a,s,1),S("x","z","y",1,1,e,n,t,r,a,2),S("x","z","y",1,-1,e,n,-t,r,a,3),S("x","y","z",1,-1,e,t,n,r,s,4),S("x","y","z",-1,-1,e,t,-n,r,s,5),this.setIndex(l),this.setAttribute("position",new cn(h,3)),this.setAttribute("normal",new cn(d,3)),this.setAttribute("uv",new cn(m,2));function S(E,_,g,I,P,C,H,U,N,V,L){let R=C/N,F=H/V,Q=C/2,Z=H/2,J=U/2,ie=N+1,$=V+1,ue=0,j=0,ge=new X;for(let _e=0;_e<$;_e++){let Ce=_e*F-Z;for(let ke=0;ke<ie;ke++){let We=ke*R-Q;ge[E]=We*I,ge[_]=Ce*P,ge[g]=J,h.push(ge.x,ge.y,ge.z),ge[E]=0,ge[_]=0,ge[g]=U>0?1:-1,d.push(ge.x,ge.y,ge.z),m.push(ke/N),m.push(1-_e/V),ue+=1}}for(let _e=0;_e<V;_e++)for(let Ce=0;Ce<N;Ce++){let ke=f+Ce+ie*_e,We=f+Ce+ie*(_e+1),re=f+(Ce+1)+ie*(_e+1),de=f+(Ce+1)+ie*_e;l.push(ke,We,de),l.push(We,re,de),j+=6}o.addGroup(v,j,L),v+=j,f+=ue}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new i(e.width,e.height,e.depth,e.widthSegments,e.heightSegments,e.depthSegments)}};function tr(i){let e={};for(let t in i){e[t]={};for(let n in i[t]){let r=i[t][n];r&&(r.isColor||r.isMatrix3||r.isMatrix4||r.isVector2||r.isVector3||r.isVector4||r.isTexture||r.isQuaternion)?r.isRenderTargetTexture?(console.warn("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),e[t][n]=null):e[t][n]=r.clone():Array.isArray(r)?e[t][n]=r.slice():e[t][n]=r}}return e}function Dt(i){let e={};for(let t=0;t<i.length;t++){let n=tr(i[t]);for(let r in n)e[r]=n[r]}return e}function lp(i){let e=[];for(let t=0;t<i.length;t++)e.push(i[t].clone());return e}function tu(i){let e=i.getRenderTarget();return e===null?i.outputColorSpace:e.isXRRenderTarget===!0?e.texture.colorSpace:et.workingColorSpace}var hp={clone:tr,merge:Dt},up=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,dp=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`,mn=class extends gi{static get type(){return"ShaderMaterial"}constructor(e){super(),this.isShaderMaterial=!0,this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=up,this.fragmentShader=dp,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,e!==void 0&&this.setValues(e)}copy(e){return super.copy(e),this.fragmentShader=e.fragmentShader,this.vertexShader=e.vertexShader,this.uniforms=tr(e.uniforms),this.uniformsGroups=lp(e.uniformsGroups),this.defines=Object.assign({},e.defines),this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.fog=e.fog,this.lights=e.lights,this.clipping=e.clipping,this.extensions=Object.assign({},e.extensions),this.glslVersion=e.glslVersion,this}toJSON(e){let t=super.toJSON(e);t.glslVersion=this.glslVersion,t.uniforms={};for(let r in this.uniforms){let a=this.uniforms[r].value;a&&a.isTexture?t.uniforms[r]={type:"t",value:a.toJSON(e).uuid}:a&&a.isColor?t.uniforms[r]={type:"c",value:a.getHex()}:a&&a.isVector2?t.uniforms[r]={type:"v2",value:a.toArray()}:a&&a.isVector3?t.uniforms[r]={type:"v3",value:a.toArray()}:a&&a.isVector4?t.uniforms[r]={type:"v4",value:a.toArray()}:a&&a.isMatrix3?t.uniforms[r]={type:"m3",value:a.toArray()}:a&&a.isMatrix4?t.uniforms[r]={type:"m4",value:a.toArray()}:t.uniforms[r]={value:a}}Object.keys(this.defines).length>0&&(t.defines=this.defines),t.vertexShader=this.vertexShader,t.fragmentShader=this.fragmentShader,t.lights=this.lights,t.clipping=this.clipping;let n={};for(let r in this.extensions)this.extensions[r]===!0&&(n[r]=!0);return Object.keys(n).length>0&&(t.extensions=n),t}},Is=class extends Kt{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new _t,this.projectionMatrix=new _t,this.projectionMatrixInverse=new _t,this.coordinateSystem=An}copy(e,t){return super.copy(e,t),this.matrixWorldInverse.copy(e.matrixWorldInverse),this.projectionMatrix.copy(e.projectionMatrix),this.projectionMatrixInverse.copy(e.projectionMatrixInverse),this.coordinateSystem=e.coordinateSystem,this}getWorldDirection(e){return super.getWorldDirection(e).negate()}updateMatrixWorld(e){super.updateMatrixWorld(e),this.matrixWorldInverse.copy(this.matrixWorld).invert()}updateWorldMatrix(e,t){super.updateWorldMatrix(e,t),this.matrixWorldInverse.copy(this.matrixWorld).invert()}clone(){return new this.constructor().copy(this)}},qn=new X,hh=new $e,uh=new $e,Nt=class extends Is{constructor(e=50,t=1,n=.1,r=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=e,this.zoom=1,this.near=n,this.far=r,this.focus=10,this.aspect=t,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.fov=e.fov,this.zoom=e.zoom,this.near=e.near,this.far=e.far,this.focus=e.focus,this.aspect=e.aspect,this.view=e.view===null?null:Object.assign({},e.view),this.filmGauge=e.filmGauge,this.filmOffset=e.filmOffset,this}setFocalLength(e){let t=.5*this.getFilmHeight()/e;this.fov=Cr*2*Math.atan(t),this.updateProjectionMatrix()}getFocalLength(){let e=Math.tan(wr*.5*this.fov);return .5*this.getFilmHeight()/e}getEffectiveFOV(){return Cr*2*Math.atan(Math.tan(wr*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(e,t,n){qn.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),t.set(qn.x,qn.y).multiplyScalar(-e/qn.z),qn.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),n.set(qn.x,qn.y).multiplyScalar(-e/qn.z)}getViewSize(e,t){return this.getViewBounds(e,hh,uh),t.subVectors(uh,hh)}setViewOffset(e,t,n,r,s,a){this.aspect=e/t,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=n,this.view.offsetY=r,this.view.width=s,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=this.near,t=e*Math.tan(wr*.5*this.fov)/this.zoom,n=2*t,r=this.aspect*n,s=-.5*r,a=this.view;if(this.view!==null&&this.view.enabled){let l=a.fullWidth,h=a.fullHeight;s+=a.offsetX*r/l,t-=a.offsetY*n/h,r*=a.width/l,n*=a.height/h}let o=this.filmOffset;o!==0&&(s+=e*o/this.getFilmWidth()),this.projectionMatrix.makePerspective(s,s+r,t,t-n,e,this.far,this.coordinateSystem),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.fov=this.fov,t.object.zoom=this.zoom,t.object.near=this.near,t.object.far=this.far,t.object.focus=this.focus,t.object.aspect=this.aspect,this.view!==null&&(t.object.view=Object.assign({},this.view)),t.object.filmGauge=this.filmGauge,t.object.filmOffset=this.filmOffset,t}},ki=-90,Bi=1,Bo=class extends Kt{constructor(e,t,n){super(),this.type="CubeCamera",this.renderTarget=n,this.coordinateSystem=null,this.activeMipmapLevel=0;let r=new Nt(ki,Bi,e,t);r.layers=this.layers,this.add(r);let s=new Nt(ki,Bi,e,t);s.layers=this.layers,this.add(s);let a=new Nt(ki,Bi,e,t);a.layers=this.layers,this.add(a);let o=new Nt(ki,Bi,e,t);o.layers=this.layers,this.add(o);let l=new Nt(ki,Bi,e,t);l.layers=this.layers,this.add(l);let h=new Nt(ki,Bi,e,t);h.layers=this.layers,this.add(h)}updateCoordinateSystem(){let e=this.coordinateSystem,t=this.children.concat(),[n,r,s,a,o,l]=t;for(let h of t)this.remove(h);if(e===An)n.up.set(0,1,0),n.lookAt(1,0,0),r.up.set(0,1,0),r.lookAt(-1,0,0),s.up.set(0,0,-1),s.lookAt(0,1,0),a.up.set(0,0,1),a.lookAt(0,-1,0),o.up.set(0,1,0),o.lookAt(0,0,1),l.up.set(0,1,0),l.lookAt(0,0,-1);else if(e===ws)n.up.set(0,-1,0),n.lookAt(-1,0,0),r.up.set(0,-1,0),r.lookAt(1,0,0),s.up.set(0,0,1),s.lookAt(0,1,0),a.up.set(0,0,-1),a.lookAt(0,-1,0),o.up.set(0,-1,0),o.lookAt(0,0,1),l.up.set(0,-1,0),l.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+e);for(let h of t)this.add(h),h.updateMatrixWorld()}update(e,t){this.parent===null&&this.updateMatrixWorld();let{renderTarget:n,activeMipmapLevel:r}=this;this.coordinateSystem!==e.coordinateSystem&&(this.coordinateSystem=e.coordinateSystem,this.updateCoordinateSystem());let[s,a,o,l,h,d]=this.children,m=e.getRenderTarget(),f=e.getActiveCubeFace(),v=e.getActiveMipmapLevel(),S=e.xr.enabled;e.xr.enabled=!1;let E=n.texture.generateMipmaps;n.texture.generateMipmaps=!1,e.setRenderTarget(n,0,r),e.render(t,s),e.setRenderTarget(n,1,r),e.render(t,a),e.setRenderTarget(n,2,r),e.render(t,o),e.setRenderTarget(n,3,r),e.render(t,l),e.setRenderTarget(n,4,r),e.render(t,h),n.texture.generateMipmaps=E,e.setRenderTarget(n,5,r),e.render(t,d),e.setRenderTarget(m,f,v),e.xr.enabled=S,n.texture.needsPMREMUpdate=!0}},Ds=class extends $t{constructor(e,t,n,r,s,a,o,l,h,d){e=e!==void 0?e:[],t=t!==void 0?t:$i,super(e,t,n,r,s,a,o,l,h,d),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(e){this.image=e}},zo=class extends Ln{constructor(e=1,t={}){super(e,e,t),this.isWebGLCubeRenderTarget=!0;let n={width:e,height:e,depth:1},r=[n,n,n,n,n,n];this.texture=new Ds(r,t.mapping,t.wrapS,t.wrapT,t.magFilter,t.minFilter,t.format,t.type,t.anisotropy,t.colorSpace),this.texture.isRenderTargetTexture=!0,this.texture.generateMipmaps=t.generateMipmaps!==void 0?t.generateMipmaps:!1,this.texture.minFilter=t.minFilter!==void 0?t.minFilter:fn}fromEquirectangularTexture(e,t){this.texture.type=t.type,this.texture.colorSpace=t.colorSpace,this.texture.generateMipmaps=t.generateMipmaps,this.texture.minFilter=t.minFilter,this.texture.magFilter=t.magFilter;let n={uniforms:{tEquirect:{value:null}},vertexShader:`

				varying vec3 vWorldDirection;

				vec3 transformDirection( in vec3 dir, in mat4 matrix ) {

					return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );

				}

				void main() {

					vWorldDirection = transformDirection( position, modelMatrix );

					#include <begin_vertex>
					#include <project_vertex>

				}
			`,fragmentShader:`

				uniform sampler2D tEquirect;

				varying vec3 vWorldDirection;

				#include <common>

				void main() {

					vec3 direction = normalize( vWorldDirection );

					vec2 sampleUV = equirectUv( direction );

					gl_FragColor = texture2D( tEquirect, sampleUV );

				}
			`},r=new Rr(5,5,5),s=new mn({name:"CubemapFromEquirect",uniforms:tr(n.uniforms),vertexShader:n.vertexShader,fragmentShader:n.fragmentShader,side:kt,blending:Zn});s.uniforms.tEquirect.value=t;let a=new an(r,s),o=t.minFilter;return t.minFilter===pi&&(t.minFilter=fn),new Bo(1,10,this).update(e,a),t.minFilter=o,a.geometry.dispose(),a.material.dispose(),this}clear(e,t,n,r){let s=e.getRenderTarget();for(let a=0;a<6;a++)e.setRenderTarget(this,a),e.clear(t,n,r);e.setRenderTarget(s)}},Va=new X,fp=new X,pp=new He,rn=class{constructor(e=new X(1,0,0),t=0){this.isPlane=!0,this.normal=e,this.constant=t}set(e,t){return this.normal.copy(e),this.constant=t,this}setComponents(e,t,n,r){return this.normal.set(e,t,n),this.constant=r,this}setFromNormalAndCoplanarPoint(e,t){return this.normal.copy(e),this.constant=-t.dot(this.normal),this}setFromCoplanarPoints(e,t,n){let r=Va.subVectors(n,t).cross(fp.subVectors(e,t)).normalize();return this.setFromNormalAndCoplanarPoint(r,e),this}copy(e){return this.normal.copy(e.normal),this.constant=e.constant,this}normalize(){let e=1/this.normal.length();return this.normal.multiplyScalar(e),this.constant*=e,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(e){return this.normal.dot(e)+this.constant}distanceToSphere(e){return this.distanceToPoint(e.center)-e.radius}projectPoint(e,t){return t.copy(e).addScaledVector(this.normal,-this.distanceToPoint(e))}intersectLine(e,t){let n=e.delta(Va),r=this.normal.dot(n);if(r===0)return this.distanceToPoint(e.start)===0?t.copy(e.start):null;let s=-(e.start.dot(this.normal)+this.constant)/r;return s<0||s>1?null:t.copy(e.start).addScaledVector(n,s)}intersectsLine(e){let t=this.distanceToPoint(e.start),n=this.distanceToPoint(e.end);return t<0&&n>0||n<0&&t>0}intersectsBox(e){return e.intersectsPlane(this)}intersectsSphere(e){return e.intersectsPlane(this)}coplanarPoint(e){return e.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(e,t){let n=t||pp.getNormalMatrix(e),r=this.coplanarPoint(Va).applyMatrix4(e),s=this.normal.applyMatrix3(n).normalize();return this.constant=-r.dot(s),this}translate(e){return this.constant-=e.dot(this.normal),this}equals(e){return e.normal.equals(this.normal)&&e.constant===this.constant}clone(){return new this.constructor().copy(this)}},ai=new Qi,us=new X,Ns=class{constructor(e=new rn,t=new rn,n=new rn,r=new rn,s=new rn,a=new rn){this.planes=[e,t,n,r,s,a]}set(e,t,n,r,s,a){let o=this.planes;return o[0].copy(e),o[1].copy(t),o[2].copy(n),o[3].copy(r),o[4].copy(s),o[5].copy(a),this}copy(e){let t=this.planes;for(let n=0;n<6;n++)t[n].copy(e.planes[n]);return this}setFromProjectionMatrix(e,t=An){let n=this.planes,r=e.elements,s=r[0],a=r[1],o=r[2],l=r[3],h=r[4],d=r[5],m=r[6],f=r[7],v=r[8],S=r[9],E=r[10],_=r[11],g=r[12],I=r[13],P=r[14],C=r[15];if(n[0].setComponents(l-s,f-h,_-v,C-g).normalize(),n[1].setComponents(l+s,f+h,_+v,C+g).normalize(),n[2].setComponents(l+a,f+d,_+S,C+I).normalize(),n[3].setComponents(l-a,f-d,_-S,C-I).normalize(),n[4].setComponents(l-o,f-m,_-E,C-P).normalize(),t===An)n[5].setComponents(l+o,f+m,_+E,C+P).normalize();else if(t===ws)n[5].setComponents(o,m,E,P).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+t);return this}intersectsObject(e){if(e.boundingSphere!==void 0)e.boundingSphere===null&&e.computeBoundingSphere(),ai.copy(e.boundingSphere).applyMatrix4(e.matrixWorld);else{let t=e.geometry;t.boundingSphere===null&&t.computeBoundingSphere(),ai.copy(t.boundingSphere).applyMatrix4(e.matrixWorld)}return this.intersectsSphere(ai)}intersectsSprite(e){return ai.center.set(0,0,0),ai.radius=.7071067811865476,ai.applyMatrix4(e.matrixWorld),this.intersectsSphere(ai)}intersectsSphere(e){let t=this.planes,n=e.center,r=-e.radius;for(let s=0;s<6;s++)if(t[s].distanceToPoint(n)<r)return!1;return!0}intersectsBox(e){let t=this.planes;for(let n=0;n<6;n++){let r=t[n];if(us.x=r.normal.x>0?e.max.x:e.min.x,us.y=r.normal.y>0?e.max.y:e.min.y,us.z=r.normal.z>0?e.max.z:e.min.z,r.distanceToPoint(us)<0)return!1}return!0}containsPoint(e){let t=this.planes;for(let n=0;n<6;n++)if(t[n].distanceToPoint(e)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}};function nu(){let i=null,e=!1,t=null,n=null;function r(s,a){t(s,a),n=i.requestAnimationFrame(r)}return{start:function(){e!==!0&&t!==null&&(n=i.requestAnimationFrame(r),e=!0)},stop:function(){i.cancelAnimationFrame(n),e=!1},setAnimationLoop:function(s){t=s},setContext:function(s){i=s}}}function mp(i){let e=new WeakMap;function t(o,l){let h=o.array,d=o.usage,m=h.byteLength,f=i.createBuffer();i.bindBuffer(l,f),i.bufferData(l,h,d),o.onUploadCallback();let v;if(h instanceof Float32Array)v=i.FLOAT;else if(h instanceof Uint16Array)o.isFloat16BufferAttribute?v=i.HALF_FLOAT:v=i.UNSIGNED_SHORT;else if(h instanceof Int16Array)v=i.SHORT;else if(h instanceof Uint32Array)v=i.UNSIGNED_INT;else if(h instanceof Int32Array)v=i.INT;else if(h instanceof Int8Array)v=i.BYTE;else if(h instanceof Uint8Array)v=i.UNSIGNED_BYTE;else if(h instanceof Uint8ClampedArray)v=i.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+h);return{buffer:f,type:v,bytesPerElement:h.BYTES_PER_ELEMENT,version:o.version,size:m}}function n(o,l,h){let d=l.array,m=l.updateRanges;if(i.bindBuffer(h,o),m.length===0)i.bufferSubData(h,0,d);else{m.sort((v,S)=>v.start-S.start);let f=0;for(let v=1;v<m.length;v++){let S=m[f],E=m[v];E.start<=S.start+S.count+1?S.count=Math.max(S.count,E.start+E.count-S.start):(++f,m[f]=E)}m.length=f+1;for(let v=0,S=m.length;v<S;v++){let E=m[v];i.bufferSubData(h,E.start*d.BYTES_PER_ELEMENT,d,E.start,E.count)}l.clearUpdateRanges()}l.onUploadCallback()}function r(o){return o.isInterleavedBufferAttribute&&(o=o.data),e.get(o)}function s(o){o.isInterleavedBufferAttribute&&(o=o.data);let l=e.get(o);l&&(i.deleteBuffer(l.buffer),e.delete(o))}function a(o,l){if(o.isInterleavedBufferAttribute&&(o=o.data),o.isGLBufferAttribute){let d=e.get(o);(!d||d.version<o.version)&&e.set(o,{buffer:o.buffer,type:o.type,bytesPerElement:o.elementSize,version:o.version});return}let h=e.get(o);if(h===void 0)e.set(o,t(o,l));else if(h.version<o.version){if(h.size!==o.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");n(h.buffer,o,l),h.version=o.version}}return{get:r,remove:s,update:a}}var Us=class i extends pn{constructor(e=1,t=1,n=1,r=1){super(),this.type="PlaneGeometry",this.parameters={width:e,height:t,widthSegments:n,heightSegments:r};let s=e/2,a=t/2,o=Math.floor(n),l=Math.floor(r),h=o+1,d=l+1,m=e/o,f=t/l,v=[],S=[],E=[],_=[];for(let g=0;g<d;g++){let I=g*f-a;for(let P=0;P<h;P++){let C=P*m-s;S.push(C,-I,0),E.push(0,0,1),_.push(P/o),_.push(1-g/l)}}for(let g=0;g<l;g++)for(let I=0;I<o;I++){let P=I+h*g,C=I+h*(g+1),H=I+1+h*(g+1),U=I+1+h*g;v.push(P,C,U),v.push(C,H,U)}this.setIndex(v),this.setAttribute("position",new cn(S,3)),this.setAttribute("normal",new cn(E,3)),this.setAttribute("uv",new cn(_,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new i(e.width,e.height,e.widthSegments,e.heightSegments)}},gp=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,vp=`#ifdef USE_ALPHAHASH
	const float ALPHA_HASH_SCALE = 0.05;
	float hash2D( vec2 value ) {
		return fract( 1.0e4 * sin( 17.0 * value.x + 0.1 * value.y ) * ( 0.1 + abs( sin( 13.0 * value.y + value.x ) ) ) );
	}
	float hash3D( vec3 value ) {
		return hash2D( vec2( hash2D( value.xy ), value.z ) );
	}
	float getAlphaHashThreshold( vec3 position ) {
		float maxDeriv = max(
			length( dFdx( position.xyz ) ),
			length( dFdy( position.xyz ) )
		);
		float pixScale = 1.0 / ( ALPHA_HASH_SCALE * maxDeriv );
		vec2 pixScales = vec2(
			exp2( floor( log2( pixScale ) ) ),
			exp2( ceil( log2( pixScale ) ) )
		);
		vec2 alpha = vec2(
			hash3D( floor( pixScales.x * position.xyz ) ),
			hash3D( floor( pixScales.y * position.xyz ) )
		);
		float lerpFactor = fract( log2( pixScale ) );
		float x = ( 1.0 - lerpFactor ) * alpha.x + lerpFactor * alpha.y;
		float a = min( lerpFactor, 1.0 - lerpFactor );
		vec3 cases = vec3(
			x * x / ( 2.0 * a * ( 1.0 - a ) ),
			( x - 0.5 * a ) / ( 1.0 - a ),
			1.0 - ( ( 1.0 - x ) * ( 1.0 - x ) / ( 2.0 * a * ( 1.0 - a ) ) )
		);
		float threshold = ( x < ( 1.0 - a ) )
			? ( ( x < a ) ? cases.x : cases.y )
			: cases.z;
		return clamp( threshold , 1.0e-6, 1.0 );
	}
#endif`,_p=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,yp=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,xp=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,bp=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,Sp=`#ifdef USE_AOMAP
	float ambientOcclusion = ( texture2D( aoMap, vAoMapUv ).r - 1.0 ) * aoMapIntensity + 1.0;
	reflectedLight.indirectDiffuse *= ambientOcclusion;
	#if defined( USE_CLEARCOAT ) 
		clearcoatSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_SHEEN ) 
		sheenSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD )
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		reflectedLight.indirectSpecular *= computeSpecularOcclusion( dotNV, ambientOcclusion, material.roughness );
	#endif
#endif`,Mp=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,wp=`#ifdef USE_BATCHING
	#if ! defined( GL_ANGLE_multi_draw )
	#define gl_DrawID _gl_DrawID
	uniform int _gl_DrawID;
	#endif
	uniform highp sampler2D batchingTexture;
	uniform highp usampler2D batchingIdTexture;
	mat4 getBatchingMatrix( const in float i ) {
		int size = textureSize( batchingTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( batchingTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( batchingTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( batchingTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( batchingTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
	float getIndirectIndex( const in int i ) {
		int size = textureSize( batchingIdTexture, 0 ).x;
		int x = i % size;
		int y = i / size;
		return float( texelFetch( batchingIdTexture, ivec2( x, y ), 0 ).r );
	}
#endif
#ifdef USE_BATCHING_COLOR
	uniform sampler2D batchingColorTexture;
	vec3 getBatchingColor( const in float i ) {
		int size = textureSize( batchingColorTexture, 0 ).x;
		int j = int( i );
		int x = j % size;
		int y = j / size;
		return texelFetch( batchingColorTexture, ivec2( x, y ), 0 ).rgb;
	}
#endif`,Ep=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,Tp=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,Ap=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,Cp=`float G_BlinnPhong_Implicit( ) {
	return 0.25;
}
float D_BlinnPhong( const in float shininess, const in float dotNH ) {
	return RECIPROCAL_PI * ( shininess * 0.5 + 1.0 ) * pow( dotNH, shininess );
}
vec3 BRDF_BlinnPhong( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 specularColor, const in float shininess ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( specularColor, 1.0, dotVH );
	float G = G_BlinnPhong_Implicit( );
	float D = D_BlinnPhong( shininess, dotNH );
	return F * ( G * D );
} // validated`,Rp=`#ifdef USE_IRIDESCENCE
	const mat3 XYZ_TO_REC709 = mat3(
		 3.2404542, -0.9692660,  0.0556434,
		-1.5371385,  1.8760108, -0.2040259,
		-0.4985314,  0.0415560,  1.0572252
	);
	vec3 Fresnel0ToIor( vec3 fresnel0 ) {
		vec3 sqrtF0 = sqrt( fresnel0 );
		return ( vec3( 1.0 ) + sqrtF0 ) / ( vec3( 1.0 ) - sqrtF0 );
	}
	vec3 IorToFresnel0( vec3 transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - vec3( incidentIor ) ) / ( transmittedIor + vec3( incidentIor ) ) );
	}
	float IorToFresnel0( float transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - incidentIor ) / ( transmittedIor + incidentIor ));
	}
	vec3 evalSensitivity( float OPD, vec3 shift ) {
		float phase = 2.0 * PI * OPD * 1.0e-9;
		vec3 val = vec3( 5.4856e-13, 4.4201e-13, 5.2481e-13 );
		vec3 pos = vec3( 1.6810e+06, 1.7953e+06, 2.2084e+06 );
		vec3 var = vec3( 4.3278e+09, 9.3046e+09, 6.6121e+09 );
		vec3 xyz = val * sqrt( 2.0 * PI * var ) * cos( pos * phase + shift ) * exp( - pow2( phase ) * var );
		xyz.x += 9.7470e-14 * sqrt( 2.0 * PI * 4.5282e+09 ) * cos( 2.2399e+06 * phase + shift[ 0 ] ) * exp( - 4.5282e+09 * pow2( phase ) );
		xyz /= 1.0685e-7;
		vec3 rgb = XYZ_TO_REC709 * xyz;
		return rgb;
	}
	vec3 evalIridescence( float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0 ) {
		vec3 I;
		float iridescenceIOR = mix( outsideIOR, eta2, smoothstep( 0.0, 0.03, thinFilmThickness ) );
		float sinTheta2Sq = pow2( outsideIOR / iridescenceIOR ) * ( 1.0 - pow2( cosTheta1 ) );
		float cosTheta2Sq = 1.0 - sinTheta2Sq;
		if ( cosTheta2Sq < 0.0 ) {
			return vec3( 1.0 );
		}
		float cosTheta2 = sqrt( cosTheta2Sq );
		float R0 = IorToFresnel0( iridescenceIOR, outsideIOR );
		float R12 = F_Schlick( R0, 1.0, cosTheta1 );
		float T121 = 1.0 - R12;
		float phi12 = 0.0;
		if ( iridescenceIOR < outsideIOR ) phi12 = PI;
		float phi21 = PI - phi12;
		vec3 baseIOR = Fresnel0ToIor( clamp( baseF0, 0.0, 0.9999 ) );		vec3 R1 = IorToFresnel0( baseIOR, iridescenceIOR );
		vec3 R23 = F_Schlick( R1, 1.0, cosTheta2 );
		vec3 phi23 = vec3( 0.0 );
		if ( baseIOR[ 0 ] < iridescenceIOR ) phi23[ 0 ] = PI;
		if ( baseIOR[ 1 ] < iridescenceIOR ) phi23[ 1 ] = PI;
		if ( baseIOR[ 2 ] < iridescenceIOR ) phi23[ 2 ] = PI;
		float OPD = 2.0 * iridescenceIOR * thinFilmThickness * cosTheta2;
		vec3 phi = vec3( phi21 ) + phi23;
		vec3 R123 = clamp( R12 * R23, 1e-5, 0.9999 );
		vec3 r123 = sqrt( R123 );
		vec3 Rs = pow2( T121 ) * R23 / ( vec3( 1.0 ) - R123 );
		vec3 C0 = R12 + Rs;
		I = C0;
		vec3 Cm = Rs - T121;
		for ( int m = 1; m <= 2; ++ m ) {
			Cm *= r123;
			vec3 Sm = 2.0 * evalSensitivity( float( m ) * OPD, float( m ) * phi );
			I += Cm * Sm;
		}
		return max( I, vec3( 0.0 ) );
	}
#endif`,Pp=`#ifdef USE_BUMPMAP
	uniform sampler2D bumpMap;
	uniform float bumpScale;
	vec2 dHdxy_fwd() {
		vec2 dSTdx = dFdx( vBumpMapUv );
		vec2 dSTdy = dFdy( vBumpMapUv );
		float Hll = bumpScale * texture2D( bumpMap, vBumpMapUv ).x;
		float dBx = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdx ).x - Hll;
		float dBy = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdy ).x - Hll;
		return vec2( dBx, dBy );
	}
	vec3 perturbNormalArb( vec3 surf_pos, vec3 surf_norm, vec2 dHdxy, float faceDirection ) {
		vec3 vSigmaX = normalize( dFdx( surf_pos.xyz ) );
		vec3 vSigmaY = normalize( dFdy( surf_pos.xyz ) );
		vec3 vN = surf_norm;
		vec3 R1 = cross( vSigmaY, vN );
		vec3 R2 = cross( vN, vSigmaX );
		float fDet = dot( vSigmaX, R1 ) * faceDirection;
		vec3 vGrad = sign( fDet ) * ( dHdxy.x * R1 + dHdxy.y * R2 );
		return normalize( abs( fDet ) * surf_norm - vGrad );
	}
#endif`,Lp=`#if NUM_CLIPPING_PLANES > 0
	vec4 plane;
	#ifdef ALPHA_TO_COVERAGE
		float distanceToPlane, distanceGradient;
		float clipOpacity = 1.0;
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
			distanceGradient = fwidth( distanceToPlane ) / 2.0;
			clipOpacity *= smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			if ( clipOpacity == 0.0 ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			float unionClipOpacity = 1.0;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
				distanceGradient = fwidth( distanceToPlane ) / 2.0;
				unionClipOpacity *= 1.0 - smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			}
			#pragma unroll_loop_end
			clipOpacity *= 1.0 - unionClipOpacity;
		#endif
		diffuseColor.a *= clipOpacity;
		if ( diffuseColor.a == 0.0 ) discard;
	#else
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			if ( dot( vClipPosition, plane.xyz ) > plane.w ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			bool clipped = true;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				clipped = ( dot( vClipPosition, plane.xyz ) > plane.w ) && clipped;
			}
			#pragma unroll_loop_end
			if ( clipped ) discard;
		#endif
	#endif
#endif`,Ip=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,Dp=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,Np=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,Up=`#if defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#elif defined( USE_COLOR )
	diffuseColor.rgb *= vColor;
#endif`,Fp=`#if defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#elif defined( USE_COLOR )
	varying vec3 vColor;
#endif`,Op=`#if defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#elif defined( USE_COLOR ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec3 vColor;
#endif`,kp=`#if defined( USE_COLOR_ALPHA )
	vColor = vec4( 1.0 );
#elif defined( USE_COLOR ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	vColor = vec3( 1.0 );
#endif
#ifdef USE_COLOR
	vColor *= color;
#endif
#ifdef USE_INSTANCING_COLOR
	vColor.xyz *= instanceColor.xyz;
#endif
#ifdef USE_BATCHING_COLOR
	vec3 batchingColor = getBatchingColor( getIndirectIndex( gl_DrawID ) );
	vColor.xyz *= batchingColor.xyz;
#endif`,Bp=`#define PI 3.141592653589793
#define PI2 6.283185307179586
#define PI_HALF 1.5707963267948966
#define RECIPROCAL_PI 0.3183098861837907
#define RECIPROCAL_PI2 0.15915494309189535
#define EPSILON 1e-6
#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
#define whiteComplement( a ) ( 1.0 - saturate( a ) )
float pow2( const in float x ) { return x*x; }
vec3 pow2( const in vec3 x ) { return x*x; }
float pow3( const in float x ) { return x*x*x; }
float pow4( const in float x ) { float x2 = x*x; return x2*x2; }
float max3( const in vec3 v ) { return max( max( v.x, v.y ), v.z ); }
float average( const in vec3 v ) { return dot( v, vec3( 0.3333333 ) ); }
highp float rand( const in vec2 uv ) {
	const highp float a = 12.9898, b = 78.233, c = 43758.5453;
	highp float dt = dot( uv.xy, vec2( a,b ) ), sn = mod( dt, PI );
	return fract( sin( sn ) * c );
}
#ifdef HIGH_PRECISION
	float precisionSafeLength( vec3 v ) { return length( v ); }
#else
	float precisionSafeLength( vec3 v ) {
		float maxComponent = max3( abs( v ) );
		return length( v / maxComponent ) * maxComponent;
	}
#endif
struct IncidentLight {
	vec3 color;
	vec3 direction;
	bool visible;
};
struct ReflectedLight {
	vec3 directDiffuse;
	vec3 directSpecular;
	vec3 indirectDiffuse;
	vec3 indirectSpecular;
};
#ifdef USE_ALPHAHASH
	varying vec3 vPosition;
#endif
vec3 transformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );
}
vec3 inverseTransformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( vec4( dir, 0.0 ) * matrix ).xyz );
}
mat3 transposeMat3( const in mat3 m ) {
	mat3 tmp;
	tmp[ 0 ] = vec3( m[ 0 ].x, m[ 1 ].x, m[ 2 ].x );
	tmp[ 1 ] = vec3( m[ 0 ].y, m[ 1 ].y, m[ 2 ].y );
	tmp[ 2 ] = vec3( m[ 0 ].z, m[ 1 ].z, m[ 2 ].z );
	return tmp;
}
bool isPerspectiveMatrix( mat4 m ) {
	return m[ 2 ][ 3 ] == - 1.0;
}
vec2 equirectUv( in vec3 dir ) {
	float u = atan( dir.z, dir.x ) * RECIPROCAL_PI2 + 0.5;
	float v = asin( clamp( dir.y, - 1.0, 1.0 ) ) * RECIPROCAL_PI + 0.5;
	return vec2( u, v );
}
vec3 BRDF_Lambert( const in vec3 diffuseColor ) {
	return RECIPROCAL_PI * diffuseColor;
}
vec3 F_Schlick( const in vec3 f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
}
float F_Schlick( const in float f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
} // validated`,zp=`#ifdef ENVMAP_TYPE_CUBE_UV
	#define cubeUV_minMipLevel 4.0
	#define cubeUV_minTileSize 16.0
	float getFace( vec3 direction ) {
		vec3 absDirection = abs( direction );
		float face = - 1.0;
		if ( absDirection.x > absDirection.z ) {
			if ( absDirection.x > absDirection.y )
				face = direction.x > 0.0 ? 0.0 : 3.0;
			else
				face = direction.y > 0.0 ? 1.0 : 4.0;
		} else {
			if ( absDirection.z > absDirection.y )
				face = direction.z > 0.0 ? 2.0 : 5.0;
			else
				face = direction.y > 0.0 ? 1.0 : 4.0;
		}
		return face;
	}
	vec2 getUV( vec3 direction, float face ) {
		vec2 uv;
		if ( face == 0.0 ) {
			uv = vec2( direction.z, direction.y ) / abs( direction.x );
		} else if ( face == 1.0 ) {
			uv = vec2( - direction.x, - direction.z ) / abs( direction.y );
		} else if ( face == 2.0 ) {
			uv = vec2( - direction.x, direction.y ) / abs( direction.z );
		} else if ( face == 3.0 ) {
			uv = vec2( - direction.z, direction.y ) / abs( direction.x );
		} else if ( face == 4.0 ) {
			uv = vec2( - direction.x, direction.z ) / abs( direction.y );
		} else {
			uv = vec2( direction.x, direction.y ) / abs( direction.z );
		}
		return 0.5 * ( uv + 1.0 );
	}
	vec3 bilinearCubeUV( sampler2D envMap, vec3 direction, float mipInt ) {
		float face = getFace( direction );
		float filterInt = max( cubeUV_minMipLevel - mipInt, 0.0 );
		mipInt = max( mipInt, cubeUV_minMipLevel );
		float faceSize = exp2( mipInt );
		highp vec2 uv = getUV( direction, face ) * ( faceSize - 2.0 ) + 1.0;
		if ( face > 2.0 ) {
			uv.y += faceSize;
			face -= 3.0;
		}
		uv.x += face * faceSize;
		uv.x += filterInt * 3.0 * cubeUV_minTileSize;
		uv.y += 4.0 * ( exp2( CUBEUV_MAX_MIP ) - faceSize );
		uv.x *= CUBEUV_TEXEL_WIDTH;
		uv.y *= CUBEUV_TEXEL_HEIGHT;
		#ifdef texture2DGradEXT
			return texture2DGradEXT( envMap, uv, vec2( 0.0 ), vec2( 0.0 ) ).rgb;
		#else
			return texture2D( envMap, uv ).rgb;
		#endif
	}
	#define cubeUV_r0 1.0
	#define cubeUV_m0 - 2.0
	#define cubeUV_r1 0.8
	#define cubeUV_m1 - 1.0
	#define cubeUV_r4 0.4
	#define cubeUV_m4 2.0
	#define cubeUV_r5 0.305
	#define cubeUV_m5 3.0
	#define cubeUV_r6 0.21
	#define cubeUV_m6 4.0
	float roughnessToMip( float roughness ) {
		float mip = 0.0;
		if ( roughness >= cubeUV_r1 ) {
			mip = ( cubeUV_r0 - roughness ) * ( cubeUV_m1 - cubeUV_m0 ) / ( cubeUV_r0 - cubeUV_r1 ) + cubeUV_m0;
		} else if ( roughness >= cubeUV_r4 ) {
			mip = ( cubeUV_r1 - roughness ) * ( cubeUV_m4 - cubeUV_m1 ) / ( cubeUV_r1 - cubeUV_r4 ) + cubeUV_m1;
		} else if ( roughness >= cubeUV_r5 ) {
			mip = ( cubeUV_r4 - roughness ) * ( cubeUV_m5 - cubeUV_m4 ) / ( cubeUV_r4 - cubeUV_r5 ) + cubeUV_m4;
		} else if ( roughness >= cubeUV_r6 ) {
			mip = ( cubeUV_r5 - roughness ) * ( cubeUV_m6 - cubeUV_m5 ) / ( cubeUV_r5 - cubeUV_r6 ) + cubeUV_m5;
		} else {
			mip = - 2.0 * log2( 1.16 * roughness );		}
		return mip;
	}
	vec4 textureCubeUV( sampler2D envMap, vec3 sampleDir, float roughness ) {
		float mip = clamp( roughnessToMip( roughness ), cubeUV_m0, CUBEUV_MAX_MIP );
		float mipF = fract( mip );
		float mipInt = floor( mip );
		vec3 color0 = bilinearCubeUV( envMap, sampleDir, mipInt );
		if ( mipF == 0.0 ) {
			return vec4( color0, 1.0 );
		} else {
			vec3 color1 = bilinearCubeUV( envMap, sampleDir, mipInt + 1.0 );
			return vec4( mix( color0, color1, mipF ), 1.0 );
		}
	}
#endif`,Gp=`vec3 transformedNormal = objectNormal;
#ifdef USE_TANGENT
	vec3 transformedTangent = objectTangent;
#endif
#ifdef USE_BATCHING
	mat3 bm = mat3( batchingMatrix );
	transformedNormal /= vec3( dot( bm[ 0 ], bm[ 0 ] ), dot( bm[ 1 ], bm[ 1 ] ), dot( bm[ 2 ], bm[ 2 ] ) );
	transformedNormal = bm * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = bm * transformedTangent;
	#endif
#endif
#ifdef USE_INSTANCING
	mat3 im = mat3( instanceMatrix );
	transformedNormal /= vec3( dot( im[ 0 ], im[ 0 ] ), dot( im[ 1 ], im[ 1 ] ), dot( im[ 2 ], im[ 2 ] ) );
	transformedNormal = im * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = im * transformedTangent;
	#endif
#endif
transformedNormal = normalMatrix * transformedNormal;
#ifdef FLIP_SIDED
	transformedNormal = - transformedNormal;
#endif
#ifdef USE_TANGENT
	transformedTangent = ( modelViewMatrix * vec4( transformedTangent, 0.0 ) ).xyz;
	#ifdef FLIP_SIDED
		transformedTangent = - transformedTangent;
	#endif
#endif`,Vp=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,Hp=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,Wp=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,Xp=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,qp="gl_FragColor = linearToOutputTexel( gl_FragColor );",Yp=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,Zp=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vec3 cameraToFrag;
		if ( isOrthographic ) {
			cameraToFrag = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToFrag = normalize( vWorldPosition - cameraPosition );
		}
		vec3 worldNormal = inverseTransformDirection( normal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vec3 reflectVec = reflect( cameraToFrag, worldNormal );
		#else
			vec3 reflectVec = refract( cameraToFrag, worldNormal, refractionRatio );
		#endif
	#else
		vec3 reflectVec = vReflect;
	#endif
	#ifdef ENVMAP_TYPE_CUBE
		vec4 envColor = textureCube( envMap, envMapRotation * vec3( flipEnvMap * reflectVec.x, reflectVec.yz ) );
	#else
		vec4 envColor = vec4( 0.0 );
	#endif
	#ifdef ENVMAP_BLENDING_MULTIPLY
		outgoingLight = mix( outgoingLight, outgoingLight * envColor.xyz, specularStrength * reflectivity );
	#elif defined( ENVMAP_BLENDING_MIX )
		outgoingLight = mix( outgoingLight, envColor.xyz, specularStrength * reflectivity );
	#elif defined( ENVMAP_BLENDING_ADD )
		outgoingLight += envColor.xyz * specularStrength * reflectivity;
	#endif
#endif`,$p=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform float flipEnvMap;
	uniform mat3 envMapRotation;
	#ifdef ENVMAP_TYPE_CUBE
		uniform samplerCube envMap;
	#else
		uniform sampler2D envMap;
	#endif
	
#endif`,Kp=`#ifdef USE_ENVMAP
	uniform float reflectivity;
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		varying vec3 vWorldPosition;
		uniform float refractionRatio;
	#else
		varying vec3 vReflect;
	#endif
#endif`,jp=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,Jp=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vWorldPosition = worldPosition.xyz;
	#else
		vec3 cameraToVertex;
		if ( isOrthographic ) {
			cameraToVertex = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToVertex = normalize( worldPosition.xyz - cameraPosition );
		}
		vec3 worldNormal = inverseTransformDirection( transformedNormal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vReflect = reflect( cameraToVertex, worldNormal );
		#else
			vReflect = refract( cameraToVertex, worldNormal, refractionRatio );
		#endif
	#endif
#endif`,Qp=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,em=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,tm=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,nm=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,im=`#ifdef USE_GRADIENTMAP
	uniform sampler2D gradientMap;
#endif
vec3 getGradientIrradiance( vec3 normal, vec3 lightDirection ) {
	float dotNL = dot( normal, lightDirection );
	vec2 coord = vec2( dotNL * 0.5 + 0.5, 0.0 );
	#ifdef USE_GRADIENTMAP
		return vec3( texture2D( gradientMap, coord ).r );
	#else
		vec2 fw = fwidth( coord ) * 0.5;
		return mix( vec3( 0.7 ), vec3( 1.0 ), smoothstep( 0.7 - fw.x, 0.7 + fw.x, coord.x ) );
	#endif
}`,rm=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,sm=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,am=`varying vec3 vViewPosition;
struct LambertMaterial {
	vec3 diffuseColor;
	float specularStrength;
};
void RE_Direct_Lambert( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Lambert( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Lambert
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,om=`uniform bool receiveShadow;
uniform vec3 ambientLightColor;
#if defined( USE_LIGHT_PROBES )
	uniform vec3 lightProbe[ 9 ];
#endif
vec3 shGetIrradianceAt( in vec3 normal, in vec3 shCoefficients[ 9 ] ) {
	float x = normal.x, y = normal.y, z = normal.z;
	vec3 result = shCoefficients[ 0 ] * 0.886227;
	result += shCoefficients[ 1 ] * 2.0 * 0.511664 * y;
	result += shCoefficients[ 2 ] * 2.0 * 0.511664 * z;
	result += shCoefficients[ 3 ] * 2.0 * 0.511664 * x;
	result += shCoefficients[ 4 ] * 2.0 * 0.429043 * x * y;
	result += shCoefficients[ 5 ] * 2.0 * 0.429043 * y * z;
	result += shCoefficients[ 6 ] * ( 0.743125 * z * z - 0.247708 );
	result += shCoefficients[ 7 ] * 2.0 * 0.429043 * x * z;
	result += shCoefficients[ 8 ] * 0.429043 * ( x * x - y * y );
	return result;
}
vec3 getLightProbeIrradiance( const in vec3 lightProbe[ 9 ], const in vec3 normal ) {
	vec3 worldNormal = inverseTransformDirection( normal, viewMatrix );
	vec3 irradiance = shGetIrradianceAt( worldNormal, lightProbe );
	return irradiance;
}
vec3 getAmbientLightIrradiance( const in vec3 ambientLightColor ) {
	vec3 irradiance = ambientLightColor;
	return irradiance;
}
float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
	float distanceFalloff = 1.0 / max( pow( lightDistance, decayExponent ), 0.01 );
	if ( cutoffDistance > 0.0 ) {
		distanceFalloff *= pow2( saturate( 1.0 - pow4( lightDistance / cutoffDistance ) ) );
	}
	return distanceFalloff;
}
float getSpotAttenuation( const in float coneCosine, const in float penumbraCosine, const in float angleCosine ) {
	return smoothstep( coneCosine, penumbraCosine, angleCosine );
}
#if NUM_DIR_LIGHTS > 0
	struct DirectionalLight {
		vec3 direction;
		vec3 color;
	};
	uniform DirectionalLight directionalLights[ NUM_DIR_LIGHTS ];
	void getDirectionalLightInfo( const in DirectionalLight directionalLight, out IncidentLight light ) {
		light.color = directionalLight.color;
		light.direction = directionalLight.direction;
		light.visible = true;
	}
#endif
#if NUM_POINT_LIGHTS > 0
	struct PointLight {
		vec3 position;
		vec3 color;
		float distance;
		float decay;
	};
	uniform PointLight pointLights[ NUM_POINT_LIGHTS ];
	void getPointLightInfo( const in PointLight pointLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = pointLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float lightDistance = length( lVector );
		light.color = pointLight.color;
		light.color *= getDistanceAttenuation( lightDistance, pointLight.distance, pointLight.decay );
		light.visible = ( light.color != vec3( 0.0 ) );
	}
#endif
#if NUM_SPOT_LIGHTS > 0
	struct SpotLight {
		vec3 position;
		vec3 direction;
		vec3 color;
		float distance;
		float decay;
		float coneCos;
		float penumbraCos;
	};
	uniform SpotLight spotLights[ NUM_SPOT_LIGHTS ];
	void getSpotLightInfo( const in SpotLight spotLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = spotLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float angleCos = dot( light.direction, spotLight.direction );
		float spotAttenuation = getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos );
		if ( spotAttenuation > 0.0 ) {
			float lightDistance = length( lVector );
			light.color = spotLight.color * spotAttenuation;
			light.color *= getDistanceAttenuation( lightDistance, spotLight.distance, spotLight.decay );
			light.visible = ( light.color != vec3( 0.0 ) );
		} else {
			light.color = vec3( 0.0 );
			light.visible = false;
		}
	}
#endif
#if NUM_RECT_AREA_LIGHTS > 0
	struct RectAreaLight {
		vec3 color;
		vec3 position;
		vec3 halfWidth;
		vec3 halfHeight;
	};
	uniform sampler2D ltc_1;	uniform sampler2D ltc_2;
	uniform RectAreaLight rectAreaLights[ NUM_RECT_AREA_LIGHTS ];
#endif
#if NUM_HEMI_LIGHTS > 0
	struct HemisphereLight {
		vec3 direction;
		vec3 skyColor;
		vec3 groundColor;
	};
	uniform HemisphereLight hemisphereLights[ NUM_HEMI_LIGHTS ];
	vec3 getHemisphereLightIrradiance( const in HemisphereLight hemiLight, const in vec3 normal ) {
		float dotNL = dot( normal, hemiLight.direction );
		float hemiDiffuseWeight = 0.5 * dotNL + 0.5;
		vec3 irradiance = mix( hemiLight.groundColor, hemiLight.skyColor, hemiDiffuseWeight );
		return irradiance;
	}
#endif`,cm=`#ifdef USE_ENVMAP
	vec3 getIBLIrradiance( const in vec3 normal ) {
		#ifdef ENVMAP_TYPE_CUBE_UV
			vec3 worldNormal = inverseTransformDirection( normal, viewMatrix );
			vec4 envMapColor = textureCubeUV( envMap, envMapRotation * worldNormal, 1.0 );
			return PI * envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	vec3 getIBLRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
		#ifdef ENVMAP_TYPE_CUBE_UV
			vec3 reflectVec = reflect( - viewDir, normal );
			reflectVec = normalize( mix( reflectVec, normal, roughness * roughness) );
			reflectVec = inverseTransformDirection( reflectVec, viewMatrix );
			vec4 envMapColor = textureCubeUV( envMap, envMapRotation * reflectVec, roughness );
			return envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	#ifdef USE_ANISOTROPY
		vec3 getIBLAnisotropyRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
			#ifdef ENVMAP_TYPE_CUBE_UV
				vec3 bentNormal = cross( bitangent, viewDir );
				bentNormal = normalize( cross( bentNormal, bitangent ) );
				bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
				return getIBLRadiance( viewDir, bentNormal, roughness );
			#else
				return vec3( 0.0 );
			#endif
		}
	#endif
#endif`,lm=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,hm=`varying vec3 vViewPosition;
struct ToonMaterial {
	vec3 diffuseColor;
};
void RE_Direct_Toon( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 irradiance = getGradientIrradiance( geometryNormal, directLight.direction ) * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Toon( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Toon
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,um=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,dm=`varying vec3 vViewPosition;
struct BlinnPhongMaterial {
	vec3 diffuseColor;
	vec3 specularColor;
	float specularShininess;
	float specularStrength;
};
void RE_Direct_BlinnPhong( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
	reflectedLight.directSpecular += irradiance * BRDF_BlinnPhong( directLight.direction, geometryViewDir, geometryNormal, material.specularColor, material.specularShininess ) * material.specularStrength;
}
void RE_IndirectDiffuse_BlinnPhong( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_BlinnPhong
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,fm=`PhysicalMaterial material;
material.diffuseColor = diffuseColor.rgb * ( 1.0 - metalnessFactor );
vec3 dxy = max( abs( dFdx( nonPerturbedNormal ) ), abs( dFdy( nonPerturbedNormal ) ) );
float geometryRoughness = max( max( dxy.x, dxy.y ), dxy.z );
material.roughness = max( roughnessFactor, 0.0525 );material.roughness += geometryRoughness;
material.roughness = min( material.roughness, 1.0 );
#ifdef IOR
	material.ior = ior;
	#ifdef USE_SPECULAR
		float specularIntensityFactor = specularIntensity;
		vec3 specularColorFactor = specularColor;
		#ifdef USE_SPECULAR_COLORMAP
			specularColorFactor *= texture2D( specularColorMap, vSpecularColorMapUv ).rgb;
		#endif
		#ifdef USE_SPECULAR_INTENSITYMAP
			specularIntensityFactor *= texture2D( specularIntensityMap, vSpecularIntensityMapUv ).a;
		#endif
		material.specularF90 = mix( specularIntensityFactor, 1.0, metalnessFactor );
	#else
		float specularIntensityFactor = 1.0;
		vec3 specularColorFactor = vec3( 1.0 );
		material.specularF90 = 1.0;
	#endif
	material.specularColor = mix( min( pow2( ( material.ior - 1.0 ) / ( material.ior + 1.0 ) ) * specularColorFactor, vec3( 1.0 ) ) * specularIntensityFactor, diffuseColor.rgb, metalnessFactor );
#else
	material.specularColor = mix( vec3( 0.04 ), diffuseColor.rgb, metalnessFactor );
	material.specularF90 = 1.0;
#endif
#ifdef USE_CLEARCOAT
	material.clearcoat = clearcoat;
	material.clearcoatRoughness = clearcoatRoughness;
	material.clearcoatF0 = vec3( 0.04 );
	material.clearcoatF90 = 1.0;
	#ifdef USE_CLEARCOATMAP
		material.clearcoat *= texture2D( clearcoatMap, vClearcoatMapUv ).x;
	#endif
	#ifdef USE_CLEARCOAT_ROUGHNESSMAP
		material.clearcoatRoughness *= texture2D( clearcoatRoughnessMap, vClearcoatRoughnessMapUv ).y;
	#endif
	material.clearcoat = saturate( material.clearcoat );	material.clearcoatRoughness = max( material.clearcoatRoughness, 0.0525 );
	material.clearcoatRoughness += geometryRoughness;
	material.clearcoatRoughness = min( material.clearcoatRoughness, 1.0 );
#endif
#ifdef USE_DISPERSION
	material.dispersion = dispersion;
#endif
#ifdef USE_IRIDESCENCE
	material.iridescence = iridescence;
	material.iridescenceIOR = iridescenceIOR;
	#ifdef USE_IRIDESCENCEMAP
		material.iridescence *= texture2D( iridescenceMap, vIridescenceMapUv ).r;
	#endif
	#ifdef USE_IRIDESCENCE_THICKNESSMAP
		material.iridescenceThickness = (iridescenceThicknessMaximum - iridescenceThicknessMinimum) * texture2D( iridescenceThicknessMap, vIridescenceThicknessMapUv ).g + iridescenceThicknessMinimum;
	#else
		material.iridescenceThickness = iridescenceThicknessMaximum;
	#endif
#endif
#ifdef USE_SHEEN
	material.sheenColor = sheenColor;
	#ifdef USE_SHEEN_COLORMAP
		material.sheenColor *= texture2D( sheenColorMap, vSheenColorMapUv ).rgb;
	#endif
	material.sheenRoughness = clamp( sheenRoughness, 0.07, 1.0 );
	#ifdef USE_SHEEN_ROUGHNESSMAP
		material.sheenRoughness *= texture2D( sheenRoughnessMap, vSheenRoughnessMapUv ).a;
	#endif
#endif
#ifdef USE_ANISOTROPY
	#ifdef USE_ANISOTROPYMAP
		mat2 anisotropyMat = mat2( anisotropyVector.x, anisotropyVector.y, - anisotropyVector.y, anisotropyVector.x );
		vec3 anisotropyPolar = texture2D( anisotropyMap, vAnisotropyMapUv ).rgb;
		vec2 anisotropyV = anisotropyMat * normalize( 2.0 * anisotropyPolar.rg - vec2( 1.0 ) ) * anisotropyPolar.b;
	#else
		vec2 anisotropyV = anisotropyVector;
	#endif
	material.anisotropy = length( anisotropyV );
	if( material.anisotropy == 0.0 ) {
		anisotropyV = vec2( 1.0, 0.0 );
	} else {
		anisotropyV /= material.anisotropy;
		material.anisotropy = saturate( material.anisotropy );
	}
	material.alphaT = mix( pow2( material.roughness ), 1.0, pow2( material.anisotropy ) );
	material.anisotropyT = tbn[ 0 ] * anisotropyV.x + tbn[ 1 ] * anisotropyV.y;
	material.anisotropyB = tbn[ 1 ] * anisotropyV.x - tbn[ 0 ] * anisotropyV.y;
#endif`,pm=`struct PhysicalMaterial {
	vec3 diffuseColor;
	float roughness;
	vec3 specularColor;
	float specularF90;
	float dispersion;
	#ifdef USE_CLEARCOAT
		float clearcoat;
		float clearcoatRoughness;
		vec3 clearcoatF0;
		float clearcoatF90;
	#endif
	#ifdef USE_IRIDESCENCE
		float iridescence;
		float iridescenceIOR;
		float iridescenceThickness;
		vec3 iridescenceFresnel;
		vec3 iridescenceF0;
	#endif
	#ifdef USE_SHEEN
		vec3 sheenColor;
		float sheenRoughness;
	#endif
	#ifdef IOR
		float ior;
	#endif
	#ifdef USE_TRANSMISSION
		float transmission;
		float transmissionAlpha;
		float thickness;
		float attenuationDistance;
		vec3 attenuationColor;
	#endif
	#ifdef USE_ANISOTROPY
		float anisotropy;
		float alphaT;
		vec3 anisotropyT;
		vec3 anisotropyB;
	#endif
};
vec3 clearcoatSpecularDirect = vec3( 0.0 );
vec3 clearcoatSpecularIndirect = vec3( 0.0 );
vec3 sheenSpecularDirect = vec3( 0.0 );
vec3 sheenSpecularIndirect = vec3(0.0 );
vec3 Schlick_to_F0( const in vec3 f, const in float f90, const in float dotVH ) {
    float x = clamp( 1.0 - dotVH, 0.0, 1.0 );
    float x2 = x * x;
    float x5 = clamp( x * x2 * x2, 0.0, 0.9999 );
    return ( f - vec3( f90 ) * x5 ) / ( 1.0 - x5 );
}
float V_GGX_SmithCorrelated( const in float alpha, const in float dotNL, const in float dotNV ) {
	float a2 = pow2( alpha );
	float gv = dotNL * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNV ) );
	float gl = dotNV * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNL ) );
	return 0.5 / max( gv + gl, EPSILON );
}
float D_GGX( const in float alpha, const in float dotNH ) {
	float a2 = pow2( alpha );
	float denom = pow2( dotNH ) * ( a2 - 1.0 ) + 1.0;
	return RECIPROCAL_PI * a2 / pow2( denom );
}
#ifdef USE_ANISOTROPY
	float V_GGX_SmithCorrelated_Anisotropic( const in float alphaT, const in float alphaB, const in float dotTV, const in float dotBV, const in float dotTL, const in float dotBL, const in float dotNV, const in float dotNL ) {
		float gv = dotNL * length( vec3( alphaT * dotTV, alphaB * dotBV, dotNV ) );
		float gl = dotNV * length( vec3( alphaT * dotTL, alphaB * dotBL, dotNL ) );
		float v = 0.5 / ( gv + gl );
		return saturate(v);
	}
	float D_GGX_Anisotropic( const in float alphaT, const in float alphaB, const in float dotNH, const in float dotTH, const in float dotBH ) {
		float a2 = alphaT * alphaB;
		highp vec3 v = vec3( alphaB * dotTH, alphaT * dotBH, a2 * dotNH );
		highp float v2 = dot( v, v );
		float w2 = a2 / v2;
		return RECIPROCAL_PI * a2 * pow2 ( w2 );
	}
#endif
#ifdef USE_CLEARCOAT
	vec3 BRDF_GGX_Clearcoat( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material) {
		vec3 f0 = material.clearcoatF0;
		float f90 = material.clearcoatF90;
		float roughness = material.clearcoatRoughness;
		float alpha = pow2( roughness );
		vec3 halfDir = normalize( lightDir + viewDir );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float dotNH = saturate( dot( normal, halfDir ) );
		float dotVH = saturate( dot( viewDir, halfDir ) );
		vec3 F = F_Schlick( f0, f90, dotVH );
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
		return F * ( V * D );
	}
#endif
vec3 BRDF_GGX( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material ) {
	vec3 f0 = material.specularColor;
	float f90 = material.specularF90;
	float roughness = material.roughness;
	float alpha = pow2( roughness );
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( f0, f90, dotVH );
	#ifdef USE_IRIDESCENCE
		F = mix( F, material.iridescenceFresnel, material.iridescence );
	#endif
	#ifdef USE_ANISOTROPY
		float dotTL = dot( material.anisotropyT, lightDir );
		float dotTV = dot( material.anisotropyT, viewDir );
		float dotTH = dot( material.anisotropyT, halfDir );
		float dotBL = dot( material.anisotropyB, lightDir );
		float dotBV = dot( material.anisotropyB, viewDir );
		float dotBH = dot( material.anisotropyB, halfDir );
		float V = V_GGX_SmithCorrelated_Anisotropic( material.alphaT, alpha, dotTV, dotBV, dotTL, dotBL, dotNV, dotNL );
		float D = D_GGX_Anisotropic( material.alphaT, alpha, dotNH, dotTH, dotBH );
	#else
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
	#endif
	return F * ( V * D );
}
vec2 LTC_Uv( const in vec3 N, const in vec3 V, const in float roughness ) {
	const float LUT_SIZE = 64.0;
	const float LUT_SCALE = ( LUT_SIZE - 1.0 ) / LUT_SIZE;
	const float LUT_BIAS = 0.5 / LUT_SIZE;
	float dotNV = saturate( dot( N, V ) );
	vec2 uv = vec2( roughness, sqrt( 1.0 - dotNV ) );
	uv = uv * LUT_SCALE + LUT_BIAS;
	return uv;
}
float LTC_ClippedSphereFormFactor( const in vec3 f ) {
	float l = length( f );
	return max( ( l * l + f.z ) / ( l + 1.0 ), 0.0 );
}
vec3 LTC_EdgeVectorFormFactor( const in vec3 v1, const in vec3 v2 ) {
	float x = dot( v1, v2 );
	float y = abs( x );
	float a = 0.8543985 + ( 0.4965155 + 0.0145206 * y ) * y;
	float b = 3.4175940 + ( 4.1616724 + y ) * y;
	float v = a / b;
	float theta_sintheta = ( x > 0.0 ) ? v : 0.5 * inversesqrt( max( 1.0 - x * x, 1e-7 ) ) - v;
	return cross( v1, v2 ) * theta_sintheta;
}
vec3 LTC_Evaluate( const in vec3 N, const in vec3 V, const in vec3 P, const in mat3 mInv, const in vec3 rectCoords[ 4 ] ) {
	vec3 v1 = rectCoords[ 1 ] - rectCoords[ 0 ];
	vec3 v2 = rectCoords[ 3 ] - rectCoords[ 0 ];
	vec3 lightNormal = cross( v1, v2 );
	if( dot( lightNormal, P - rectCoords[ 0 ] ) < 0.0 ) return vec3( 0.0 );
	vec3 T1, T2;
	T1 = normalize( V - N * dot( V, N ) );
	T2 = - cross( N, T1 );
	mat3 mat = mInv * transposeMat3( mat3( T1, T2, N ) );
	vec3 coords[ 4 ];
	coords[ 0 ] = mat * ( rectCoords[ 0 ] - P );
	coords[ 1 ] = mat * ( rectCoords[ 1 ] - P );
	coords[ 2 ] = mat * ( rectCoords[ 2 ] - P );
	coords[ 3 ] = mat * ( rectCoords[ 3 ] - P );
	coords[ 0 ] = normalize( coords[ 0 ] );
	coords[ 1 ] = normalize( coords[ 1 ] );
	coords[ 2 ] = normalize( coords[ 2 ] );
	coords[ 3 ] = normalize( coords[ 3 ] );
	vec3 vectorFormFactor = vec3( 0.0 );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 0 ], coords[ 1 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 1 ], coords[ 2 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 2 ], coords[ 3 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 3 ], coords[ 0 ] );
	float result = LTC_ClippedSphereFormFactor( vectorFormFactor );
	return vec3( result );
}
#if defined( USE_SHEEN )
float D_Charlie( float roughness, float dotNH ) {
	float alpha = pow2( roughness );
	float invAlpha = 1.0 / alpha;
	float cos2h = dotNH * dotNH;
	float sin2h = max( 1.0 - cos2h, 0.0078125 );
	return ( 2.0 + invAlpha ) * pow( sin2h, invAlpha * 0.5 ) / ( 2.0 * PI );
}
float V_Neubelt( float dotNV, float dotNL ) {
	return saturate( 1.0 / ( 4.0 * ( dotNL + dotNV - dotNL * dotNV ) ) );
}
vec3 BRDF_Sheen( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, vec3 sheenColor, const in float sheenRoughness ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float D = D_Charlie( sheenRoughness, dotNH );
	float V = V_Neubelt( dotNV, dotNL );
	return sheenColor * ( D * V );
}
#endif
float IBLSheenBRDF( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	float r2 = roughness * roughness;
	float a = roughness < 0.25 ? -339.2 * r2 + 161.4 * roughness - 25.9 : -8.48 * r2 + 14.3 * roughness - 9.95;
	float b = roughness < 0.25 ? 44.0 * r2 - 23.7 * roughness + 3.26 : 1.97 * r2 - 3.27 * roughness + 0.72;
	float DG = exp( a * dotNV + b ) + ( roughness < 0.25 ? 0.0 : 0.1 * ( roughness - 0.25 ) );
	return saturate( DG * RECIPROCAL_PI );
}
vec2 DFGApprox( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	const vec4 c0 = vec4( - 1, - 0.0275, - 0.572, 0.022 );
	const vec4 c1 = vec4( 1, 0.0425, 1.04, - 0.04 );
	vec4 r = roughness * c0 + c1;
	float a004 = min( r.x * r.x, exp2( - 9.28 * dotNV ) ) * r.x + r.y;
	vec2 fab = vec2( - 1.04, 1.04 ) * a004 + r.zw;
	return fab;
}
vec3 EnvironmentBRDF( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness ) {
	vec2 fab = DFGApprox( normal, viewDir, roughness );
	return specularColor * fab.x + specularF90 * fab.y;
}
#ifdef USE_IRIDESCENCE
void computeMultiscatteringIridescence( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float iridescence, const in vec3 iridescenceF0, const in float roughness, inout vec3 singleScatter, inout vec3 multiScatter ) {
#else
void computeMultiscattering( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness, inout vec3 singleScatter, inout vec3 multiScatter ) {
#endif
	vec2 fab = DFGApprox( normal, viewDir, roughness );
	#ifdef USE_IRIDESCENCE
		vec3 Fr = mix( specularColor, iridescenceF0, iridescence );
	#else
		vec3 Fr = specularColor;
	#endif
	vec3 FssEss = Fr * fab.x + specularF90 * fab.y;
	float Ess = fab.x + fab.y;
	float Ems = 1.0 - Ess;
	vec3 Favg = Fr + ( 1.0 - Fr ) * 0.047619;	vec3 Fms = FssEss * Favg / ( 1.0 - Ems * Favg );
	singleScatter += FssEss;
	multiScatter += Fms * Ems;
}
#if NUM_RECT_AREA_LIGHTS > 0
	void RE_Direct_RectArea_Physical( const in RectAreaLight rectAreaLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
		vec3 normal = geometryNormal;
		vec3 viewDir = geometryViewDir;
		vec3 position = geometryPosition;
		vec3 lightPos = rectAreaLight.position;
		vec3 halfWidth = rectAreaLight.halfWidth;
		vec3 halfHeight = rectAreaLight.halfHeight;
		vec3 lightColor = rectAreaLight.color;
		float roughness = material.roughness;
		vec3 rectCoords[ 4 ];
		rectCoords[ 0 ] = lightPos + halfWidth - halfHeight;		rectCoords[ 1 ] = lightPos - halfWidth - halfHeight;
		rectCoords[ 2 ] = lightPos - halfWidth + halfHeight;
		rectCoords[ 3 ] = lightPos + halfWidth + halfHeight;
		vec2 uv = LTC_Uv( normal, viewDir, roughness );
		vec4 t1 = texture2D( ltc_1, uv );
		vec4 t2 = texture2D( ltc_2, uv );
		mat3 mInv = mat3(
			vec3( t1.x, 0, t1.y ),
			vec3(    0, 1,    0 ),
			vec3( t1.z, 0, t1.w )
		);
		vec3 fresnel = ( material.specularColor * t2.x + ( vec3( 1.0 ) - material.specularColor ) * t2.y );
		reflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );
		reflectedLight.directDiffuse += lightColor * material.diffuseColor * LTC_Evaluate( normal, viewDir, position, mat3( 1.0 ), rectCoords );
	}
#endif
void RE_Direct_Physical( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	#ifdef USE_CLEARCOAT
		float dotNLcc = saturate( dot( geometryClearcoatNormal, directLight.direction ) );
		vec3 ccIrradiance = dotNLcc * directLight.color;
		clearcoatSpecularDirect += ccIrradiance * BRDF_GGX_Clearcoat( directLight.direction, geometryViewDir, geometryClearcoatNormal, material );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularDirect += irradiance * BRDF_Sheen( directLight.direction, geometryViewDir, geometryNormal, material.sheenColor, material.sheenRoughness );
	#endif
	reflectedLight.directSpecular += irradiance * BRDF_GGX( directLight.direction, geometryViewDir, geometryNormal, material );
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Physical( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectSpecular_Physical( const in vec3 radiance, const in vec3 irradiance, const in vec3 clearcoatRadiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight) {
	#ifdef USE_CLEARCOAT
		clearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, geometryViewDir, material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularIndirect += irradiance * material.sheenColor * IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
	#endif
	vec3 singleScattering = vec3( 0.0 );
	vec3 multiScattering = vec3( 0.0 );
	vec3 cosineWeightedIrradiance = irradiance * RECIPROCAL_PI;
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( geometryNormal, geometryViewDir, material.specularColor, material.specularF90, material.iridescence, material.iridescenceFresnel, material.roughness, singleScattering, multiScattering );
	#else
		computeMultiscattering( geometryNormal, geometryViewDir, material.specularColor, material.specularF90, material.roughness, singleScattering, multiScattering );
	#endif
	vec3 totalScattering = singleScattering + multiScattering;
	vec3 diffuse = material.diffuseColor * ( 1.0 - max( max( totalScattering.r, totalScattering.g ), totalScattering.b ) );
	reflectedLight.indirectSpecular += radiance * singleScattering;
	reflectedLight.indirectSpecular += multiScattering * cosineWeightedIrradiance;
	reflectedLight.indirectDiffuse += diffuse * cosineWeightedIrradiance;
}
#define RE_Direct				RE_Direct_Physical
#define RE_Direct_RectArea		RE_Direct_RectArea_Physical
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Physical
#define RE_IndirectSpecular		RE_IndirectSpecular_Physical
float computeSpecularOcclusion( const in float dotNV, const in float ambientOcclusion, const in float roughness ) {
	return saturate( pow( dotNV + ambientOcclusion, exp2( - 16.0 * roughness - 1.0 ) ) - 1.0 + ambientOcclusion );
}`,mm=`
vec3 geometryPosition = - vViewPosition;
vec3 geometryNormal = normal;
vec3 geometryViewDir = ( isOrthographic ) ? vec3( 0, 0, 1 ) : normalize( vViewPosition );
vec3 geometryClearcoatNormal = vec3( 0.0 );
#ifdef USE_CLEARCOAT
	geometryClearcoatNormal = clearcoatNormal;
#endif
#ifdef USE_IRIDESCENCE
	float dotNVi = saturate( dot( normal, geometryViewDir ) );
	if ( material.iridescenceThickness == 0.0 ) {
		material.iridescence = 0.0;
	} else {
		material.iridescence = saturate( material.iridescence );
	}
	if ( material.iridescence > 0.0 ) {
		material.iridescenceFresnel = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor );
		material.iridescenceF0 = Schlick_to_F0( material.iridescenceFresnel, 1.0, dotNVi );
	}
#endif
IncidentLight directLight;
#if ( NUM_POINT_LIGHTS > 0 ) && defined( RE_Direct )
	PointLight pointLight;
	#if defined( USE_SHADOWMAP ) && NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHTS; i ++ ) {
		pointLight = pointLights[ i ];
		getPointLightInfo( pointLight, geometryPosition, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_POINT_LIGHT_SHADOWS )
		pointLightShadow = pointLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getPointShadow( pointShadowMap[ i ], pointLightShadow.shadowMapSize, pointLightShadow.shadowIntensity, pointLightShadow.shadowBias, pointLightShadow.shadowRadius, vPointShadowCoord[ i ], pointLightShadow.shadowCameraNear, pointLightShadow.shadowCameraFar ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SPOT_LIGHTS > 0 ) && defined( RE_Direct )
	SpotLight spotLight;
	vec4 spotColor;
	vec3 spotLightCoord;
	bool inSpotLightMap;
	#if defined( USE_SHADOWMAP ) && NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHTS; i ++ ) {
		spotLight = spotLights[ i ];
		getSpotLightInfo( spotLight, geometryPosition, directLight );
		#if ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#define SPOT_LIGHT_MAP_INDEX UNROLLED_LOOP_INDEX
		#elif ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		#define SPOT_LIGHT_MAP_INDEX NUM_SPOT_LIGHT_MAPS
		#else
		#define SPOT_LIGHT_MAP_INDEX ( UNROLLED_LOOP_INDEX - NUM_SPOT_LIGHT_SHADOWS + NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#endif
		#if ( SPOT_LIGHT_MAP_INDEX < NUM_SPOT_LIGHT_MAPS )
			spotLightCoord = vSpotLightCoord[ i ].xyz / vSpotLightCoord[ i ].w;
			inSpotLightMap = all( lessThan( abs( spotLightCoord * 2. - 1. ), vec3( 1.0 ) ) );
			spotColor = texture2D( spotLightMap[ SPOT_LIGHT_MAP_INDEX ], spotLightCoord.xy );
			directLight.color = inSpotLightMap ? directLight.color * spotColor.rgb : directLight.color;
		#endif
		#undef SPOT_LIGHT_MAP_INDEX
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		spotLightShadow = spotLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( spotShadowMap[ i ], spotLightShadow.shadowMapSize, spotLightShadow.shadowIntensity, spotLightShadow.shadowBias, spotLightShadow.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_DIR_LIGHTS > 0 ) && defined( RE_Direct )
	DirectionalLight directionalLight;
	#if defined( USE_SHADOWMAP ) && NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHTS; i ++ ) {
		directionalLight = directionalLights[ i ];
		getDirectionalLightInfo( directionalLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_DIR_LIGHT_SHADOWS )
		directionalLightShadow = directionalLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( directionalShadowMap[ i ], directionalLightShadow.shadowMapSize, directionalLightShadow.shadowIntensity, directionalLightShadow.shadowBias, directionalLightShadow.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_RECT_AREA_LIGHTS > 0 ) && defined( RE_Direct_RectArea )
	RectAreaLight rectAreaLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_RECT_AREA_LIGHTS; i ++ ) {
		rectAreaLight = rectAreaLights[ i ];
		RE_Direct_RectArea( rectAreaLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if defined( RE_IndirectDiffuse )
	vec3 iblIrradiance = vec3( 0.0 );
	vec3 irradiance = getAmbientLightIrradiance( ambientLightColor );
	#if defined( USE_LIGHT_PROBES )
		irradiance += getLightProbeIrradiance( lightProbe, geometryNormal );
	#endif
	#if ( NUM_HEMI_LIGHTS > 0 )
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_HEMI_LIGHTS; i ++ ) {
			irradiance += getHemisphereLightIrradiance( hemisphereLights[ i ], geometryNormal );
		}
		#pragma unroll_loop_end
	#endif
#endif
#if defined( RE_IndirectSpecular )
	vec3 radiance = vec3( 0.0 );
	vec3 clearcoatRadiance = vec3( 0.0 );
#endif`,gm=`#if defined( RE_IndirectDiffuse )
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		vec3 lightMapIrradiance = lightMapTexel.rgb * lightMapIntensity;
		irradiance += lightMapIrradiance;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD ) && defined( ENVMAP_TYPE_CUBE_UV )
		iblIrradiance += getIBLIrradiance( geometryNormal );
	#endif
#endif
#if defined( USE_ENVMAP ) && defined( RE_IndirectSpecular )
	#ifdef USE_ANISOTROPY
		radiance += getIBLAnisotropyRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
	#else
		radiance += getIBLRadiance( geometryViewDir, geometryNormal, material.roughness );
	#endif
	#ifdef USE_CLEARCOAT
		clearcoatRadiance += getIBLRadiance( geometryViewDir, geometryClearcoatNormal, material.clearcoatRoughness );
	#endif
#endif`,vm=`#if defined( RE_IndirectDiffuse )
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,_m=`#if defined( USE_LOGDEPTHBUF )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,ym=`#if defined( USE_LOGDEPTHBUF )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,xm=`#ifdef USE_LOGDEPTHBUF
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,bm=`#ifdef USE_LOGDEPTHBUF
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,Sm=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,Mm=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,wm=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
	#if defined( USE_POINTS_UV )
		vec2 uv = vUv;
	#else
		vec2 uv = ( uvTransform * vec3( gl_PointCoord.x, 1.0 - gl_PointCoord.y, 1 ) ).xy;
	#endif
#endif
#ifdef USE_MAP
	diffuseColor *= texture2D( map, uv );
#endif
#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, uv ).g;
#endif`,Em=`#if defined( USE_POINTS_UV )
	varying vec2 vUv;
#else
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		uniform mat3 uvTransform;
	#endif
#endif
#ifdef USE_MAP
	uniform sampler2D map;
#endif
#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,Tm=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,Am=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,Cm=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,Rm=`#if defined( USE_MORPHCOLORS )
	vColor *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		#if defined( USE_COLOR_ALPHA )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ) * morphTargetInfluences[ i ];
		#elif defined( USE_COLOR )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ).rgb * morphTargetInfluences[ i ];
		#endif
	}
#endif`,Pm=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,Lm=`#ifdef USE_MORPHTARGETS
	#ifndef USE_INSTANCING_MORPH
		uniform float morphTargetBaseInfluence;
		uniform float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	#endif
	uniform sampler2DArray morphTargetsTexture;
	uniform ivec2 morphTargetsTextureSize;
	vec4 getMorph( const in int vertexIndex, const in int morphTargetIndex, const in int offset ) {
		int texelIndex = vertexIndex * MORPHTARGETS_TEXTURE_STRIDE + offset;
		int y = texelIndex / morphTargetsTextureSize.x;
		int x = texelIndex - y * morphTargetsTextureSize.x;
		ivec3 morphUV = ivec3( x, y, morphTargetIndex );
		return texelFetch( morphTargetsTexture, morphUV, 0 );
	}
#endif`,Im=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,Dm=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#ifdef FLAT_SHADED
	vec3 fdx = dFdx( vViewPosition );
	vec3 fdy = dFdy( vViewPosition );
	vec3 normal = normalize( cross( fdx, fdy ) );
#else
	vec3 normal = normalize( vNormal );
	#ifdef DOUBLE_SIDED
		normal *= faceDirection;
	#endif
#endif
#if defined( USE_NORMALMAP_TANGENTSPACE ) || defined( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY )
	#ifdef USE_TANGENT
		mat3 tbn = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn = getTangentFrame( - vViewPosition, normal,
		#if defined( USE_NORMALMAP )
			vNormalMapUv
		#elif defined( USE_CLEARCOAT_NORMALMAP )
			vClearcoatNormalMapUv
		#else
			vUv
		#endif
		);
	#endif
	#if defined( DOUBLE_SIDED ) && ! defined( FLAT_SHADED )
		tbn[0] *= faceDirection;
		tbn[1] *= faceDirection;
	#endif
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	#ifdef USE_TANGENT
		mat3 tbn2 = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn2 = getTangentFrame( - vViewPosition, normal, vClearcoatNormalMapUv );
	#endif
	#if defined( DOUBLE_SIDED ) && ! defined( FLAT_SHADED )
		tbn2[0] *= faceDirection;
		tbn2[1] *= faceDirection;
	#endif
#endif
vec3 nonPerturbedNormal = normal;`,Nm=`#ifdef USE_NORMALMAP_OBJECTSPACE
	normal = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#ifdef FLIP_SIDED
		normal = - normal;
	#endif
	#ifdef DOUBLE_SIDED
		normal = normal * faceDirection;
	#endif
	normal = normalize( normalMatrix * normal );
#elif defined( USE_NORMALMAP_TANGENTSPACE )
	vec3 mapN = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	mapN.xy *= normalScale;
	normal = normalize( tbn * mapN );
#elif defined( USE_BUMPMAP )
	normal = perturbNormalArb( - vViewPosition, normal, dHdxy_fwd(), faceDirection );
#endif`,Um=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,Fm=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,Om=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
	#endif
#endif`,km=`#ifdef USE_NORMALMAP
	uniform sampler2D normalMap;
	uniform vec2 normalScale;
#endif
#ifdef USE_NORMALMAP_OBJECTSPACE
	uniform mat3 normalMatrix;
#endif
#if ! defined ( USE_TANGENT ) && ( defined ( USE_NORMALMAP_TANGENTSPACE ) || defined ( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY ) )
	mat3 getTangentFrame( vec3 eye_pos, vec3 surf_norm, vec2 uv ) {
		vec3 q0 = dFdx( eye_pos.xyz );
		vec3 q1 = dFdy( eye_pos.xyz );
		vec2 st0 = dFdx( uv.st );
		vec2 st1 = dFdy( uv.st );
		vec3 N = surf_norm;
		vec3 q1perp = cross( q1, N );
		vec3 q0perp = cross( N, q0 );
		vec3 T = q1perp * st0.x + q0perp * st1.x;
		vec3 B = q1perp * st0.y + q0perp * st1.y;
		float det = max( dot( T, T ), dot( B, B ) );
		float scale = ( det == 0.0 ) ? 0.0 : inversesqrt( det );
		return mat3( T * scale, B * scale, N );
	}
#endif`,Bm=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,zm=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,Gm=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,Vm=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,Hm=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,Wm=`vec3 packNormalToRGB( const in vec3 normal ) {
	return normalize( normal ) * 0.5 + 0.5;
}
vec3 unpackRGBToNormal( const in vec3 rgb ) {
	return 2.0 * rgb.xyz - 1.0;
}
const float PackUpscale = 256. / 255.;const float UnpackDownscale = 255. / 256.;const float ShiftRight8 = 1. / 256.;
const float Inv255 = 1. / 255.;
const vec4 PackFactors = vec4( 1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0 );
const vec2 UnpackFactors2 = vec2( UnpackDownscale, 1.0 / PackFactors.g );
const vec3 UnpackFactors3 = vec3( UnpackDownscale / PackFactors.rg, 1.0 / PackFactors.b );
const vec4 UnpackFactors4 = vec4( UnpackDownscale / PackFactors.rgb, 1.0 / PackFactors.a );
vec4 packDepthToRGBA( const in float v ) {
	if( v <= 0.0 )
		return vec4( 0., 0., 0., 0. );
	if( v >= 1.0 )
		return vec4( 1., 1., 1., 1. );
	float vuf;
	float af = modf( v * PackFactors.a, vuf );
	float bf = modf( vuf * ShiftRight8, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec4( vuf * Inv255, gf * PackUpscale, bf * PackUpscale, af );
}
vec3 packDepthToRGB( const in float v ) {
	if( v <= 0.0 )
		return vec3( 0., 0., 0. );
	if( v >= 1.0 )
		return vec3( 1., 1., 1. );
	float vuf;
	float bf = modf( v * PackFactors.b, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec3( vuf * Inv255, gf * PackUpscale, bf );
}
vec2 packDepthToRG( const in float v ) {
	if( v <= 0.0 )
		return vec2( 0., 0. );
	if( v >= 1.0 )
		return vec2( 1., 1. );
	float vuf;
	float gf = modf( v * 256., vuf );
	return vec2( vuf * Inv255, gf );
}
float unpackRGBAToDepth( const in vec4 v ) {
	return dot( v, UnpackFactors4 );
}
float unpackRGBToDepth( const in vec3 v ) {
	return dot( v, UnpackFactors3 );
}
float unpackRGToDepth( const in vec2 v ) {
	return v.r * UnpackFactors2.r + v.g * UnpackFactors2.g;
}
vec4 pack2HalfToRGBA( const in vec2 v ) {
	vec4 r = vec4( v.x, fract( v.x * 255.0 ), v.y, fract( v.y * 255.0 ) );
	return vec4( r.x - r.y / 255.0, r.y, r.z - r.w / 255.0, r.w );
}
vec2 unpackRGBATo2Half( const in vec4 v ) {
	return vec2( v.x + ( v.y / 255.0 ), v.z + ( v.w / 255.0 ) );
}
float viewZToOrthographicDepth( const in float viewZ, const in float near, const in float far ) {
	return ( viewZ + near ) / ( near - far );
}
float orthographicDepthToViewZ( const in float depth, const in float near, const in float far ) {
	return depth * ( near - far ) - near;
}
float viewZToPerspectiveDepth( const in float viewZ, const in float near, const in float far ) {
	return ( ( near + viewZ ) * far ) / ( ( far - near ) * viewZ );
}
float perspectiveDepthToViewZ( const in float depth, const in float near, const in float far ) {
	return ( near * far ) / ( ( far - near ) * depth - far );
}`,Xm=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,qm=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,Ym=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,Zm=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,$m=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,Km=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,jm=`#if NUM_SPOT_LIGHT_COORDS > 0
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#if NUM_SPOT_LIGHT_MAPS > 0
	uniform sampler2D spotLightMap[ NUM_SPOT_LIGHT_MAPS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform sampler2D directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		uniform sampler2D spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform sampler2D pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
	float texture2DCompare( sampler2D depths, vec2 uv, float compare ) {
		return step( compare, unpackRGBAToDepth( texture2D( depths, uv ) ) );
	}
	vec2 texture2DDistribution( sampler2D shadow, vec2 uv ) {
		return unpackRGBATo2Half( texture2D( shadow, uv ) );
	}
	float VSMShadow (sampler2D shadow, vec2 uv, float compare ){
		float occlusion = 1.0;
		vec2 distribution = texture2DDistribution( shadow, uv );
		float hard_shadow = step( compare , distribution.x );
		if (hard_shadow != 1.0 ) {
			float distance = compare - distribution.x ;
			float variance = max( 0.00000, distribution.y * distribution.y );
			float softness_probability = variance / (variance + distance * distance );			softness_probability = clamp( ( softness_probability - 0.3 ) / ( 0.95 - 0.3 ), 0.0, 1.0 );			occlusion = clamp( max( hard_shadow, softness_probability ), 0.0, 1.0 );
		}
		return occlusion;
	}
	float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
		float shadow = 1.0;
		shadowCoord.xyz /= shadowCoord.w;
		shadowCoord.z += shadowBias;
		bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
		bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
		if ( frustumTest ) {
		#if defined( SHADOWMAP_TYPE_PCF )
			vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
			float dx0 = - texelSize.x * shadowRadius;
			float dy0 = - texelSize.y * shadowRadius;
			float dx1 = + texelSize.x * shadowRadius;
			float dy1 = + texelSize.y * shadowRadius;
			float dx2 = dx0 / 2.0;
			float dy2 = dy0 / 2.0;
			float dx3 = dx1 / 2.0;
			float dy3 = dy1 / 2.0;
			shadow = (
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx0, dy0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( 0.0, dy0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx1, dy0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx2, dy2 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( 0.0, dy2 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx3, dy2 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx0, 0.0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx2, 0.0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy, shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx3, 0.0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx1, 0.0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx2, dy3 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( 0.0, dy3 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx3, dy3 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx0, dy1 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( 0.0, dy1 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, shadowCoord.xy + vec2( dx1, dy1 ), shadowCoord.z )
			) * ( 1.0 / 17.0 );
		#elif defined( SHADOWMAP_TYPE_PCF_SOFT )
			vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
			float dx = texelSize.x;
			float dy = texelSize.y;
			vec2 uv = shadowCoord.xy;
			vec2 f = fract( uv * shadowMapSize + 0.5 );
			uv -= f * texelSize;
			shadow = (
				texture2DCompare( shadowMap, uv, shadowCoord.z ) +
				texture2DCompare( shadowMap, uv + vec2( dx, 0.0 ), shadowCoord.z ) +
				texture2DCompare( shadowMap, uv + vec2( 0.0, dy ), shadowCoord.z ) +
				texture2DCompare( shadowMap, uv + texelSize, shadowCoord.z ) +
				mix( texture2DCompare( shadowMap, uv + vec2( -dx, 0.0 ), shadowCoord.z ),
					 texture2DCompare( shadowMap, uv + vec2( 2.0 * dx, 0.0 ), shadowCoord.z ),
					 f.x ) +
				mix( texture2DCompare( shadowMap, uv + vec2( -dx, dy ), shadowCoord.z ),
					 texture2DCompare( shadowMap, uv + vec2( 2.0 * dx, dy ), shadowCoord.z ),
					 f.x ) +
				mix( texture2DCompare( shadowMap, uv + vec2( 0.0, -dy ), shadowCoord.z ),
					 texture2DCompare( shadowMap, uv + vec2( 0.0, 2.0 * dy ), shadowCoord.z ),
					 f.y ) +
				mix( texture2DCompare( shadowMap, uv + vec2( dx, -dy ), shadowCoord.z ),
					 texture2DCompare( shadowMap, uv + vec2( dx, 2.0 * dy ), shadowCoord.z ),
					 f.y ) +
				mix( mix( texture2DCompare( shadowMap, uv + vec2( -dx, -dy ), shadowCoord.z ),
						  texture2DCompare( shadowMap, uv + vec2( 2.0 * dx, -dy ), shadowCoord.z ),
						  f.x ),
					 mix( texture2DCompare( shadowMap, uv + vec2( -dx, 2.0 * dy ), shadowCoord.z ),
						  texture2DCompare( shadowMap, uv + vec2( 2.0 * dx, 2.0 * dy ), shadowCoord.z ),
						  f.x ),
					 f.y )
			) * ( 1.0 / 9.0 );
		#elif defined( SHADOWMAP_TYPE_VSM )
			shadow = VSMShadow( shadowMap, shadowCoord.xy, shadowCoord.z );
		#else
			shadow = texture2DCompare( shadowMap, shadowCoord.xy, shadowCoord.z );
		#endif
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	vec2 cubeToUV( vec3 v, float texelSizeY ) {
		vec3 absV = abs( v );
		float scaleToCube = 1.0 / max( absV.x, max( absV.y, absV.z ) );
		absV *= scaleToCube;
		v *= scaleToCube * ( 1.0 - 2.0 * texelSizeY );
		vec2 planar = v.xy;
		float almostATexel = 1.5 * texelSizeY;
		float almostOne = 1.0 - almostATexel;
		if ( absV.z >= almostOne ) {
			if ( v.z > 0.0 )
				planar.x = 4.0 - v.x;
		} else if ( absV.x >= almostOne ) {
			float signX = sign( v.x );
			planar.x = v.z * signX + 2.0 * signX;
		} else if ( absV.y >= almostOne ) {
			float signY = sign( v.y );
			planar.x = v.x + 2.0 * signY + 2.0;
			planar.y = v.z * signY - 2.0;
		}
		return vec2( 0.125, 0.25 ) * planar + vec2( 0.375, 0.75 );
	}
	float getPointShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		
		float lightToPositionLength = length( lightToPosition );
		if ( lightToPositionLength - shadowCameraFar <= 0.0 && lightToPositionLength - shadowCameraNear >= 0.0 ) {
			float dp = ( lightToPositionLength - shadowCameraNear ) / ( shadowCameraFar - shadowCameraNear );			dp += shadowBias;
			vec3 bd3D = normalize( lightToPosition );
			vec2 texelSize = vec2( 1.0 ) / ( shadowMapSize * vec2( 4.0, 2.0 ) );
			#if defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_PCF_SOFT ) || defined( SHADOWMAP_TYPE_VSM )
				vec2 offset = vec2( - 1, 1 ) * shadowRadius * texelSize.y;
				shadow = (
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.xyy, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.yyy, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.xyx, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.yyx, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.xxy, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.yxy, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.xxx, texelSize.y ), dp ) +
					texture2DCompare( shadowMap, cubeToUV( bd3D + offset.yxx, texelSize.y ), dp )
				) * ( 1.0 / 9.0 );
			#else
				shadow = texture2DCompare( shadowMap, cubeToUV( bd3D, texelSize.y ), dp );
			#endif
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
#endif`,Jm=`#if NUM_SPOT_LIGHT_COORDS > 0
	uniform mat4 spotLightMatrix[ NUM_SPOT_LIGHT_COORDS ];
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform mat4 directionalShadowMatrix[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform mat4 pointShadowMatrix[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
#endif`,Qm=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
	vec3 shadowWorldNormal = inverseTransformDirection( transformedNormal, viewMatrix );
	vec4 shadowWorldPosition;
#endif
#if defined( USE_SHADOWMAP )
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * directionalLightShadows[ i ].shadowNormalBias, 0 );
			vDirectionalShadowCoord[ i ] = directionalShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * pointLightShadows[ i ].shadowNormalBias, 0 );
			vPointShadowCoord[ i ] = pointShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
#endif
#if NUM_SPOT_LIGHT_COORDS > 0
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_COORDS; i ++ ) {
		shadowWorldPosition = worldPosition;
		#if ( defined( USE_SHADOWMAP ) && UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
			shadowWorldPosition.xyz += shadowWorldNormal * spotLightShadows[ i ].shadowNormalBias;
		#endif
		vSpotLightCoord[ i ] = spotLightMatrix[ i ] * shadowWorldPosition;
	}
	#pragma unroll_loop_end
#endif`,eg=`float getShadowMask() {
	float shadow = 1.0;
	#ifdef USE_SHADOWMAP
	#if NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
		directionalLight = directionalLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( directionalShadowMap[ i ], directionalLight.shadowMapSize, directionalLight.shadowIntensity, directionalLight.shadowBias, directionalLight.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_SHADOWS; i ++ ) {
		spotLight = spotLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( spotShadowMap[ i ], spotLight.shadowMapSize, spotLight.shadowIntensity, spotLight.shadowBias, spotLight.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
		pointLight = pointLightShadows[ i ];
		shadow *= receiveShadow ? getPointShadow( pointShadowMap[ i ], pointLight.shadowMapSize, pointLight.shadowIntensity, pointLight.shadowBias, pointLight.shadowRadius, vPointShadowCoord[ i ], pointLight.shadowCameraNear, pointLight.shadowCameraFar ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#endif
	return shadow;
}`,tg=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,ng=`#ifdef USE_SKINNING
	uniform mat4 bindMatrix;
	uniform mat4 bindMatrixInverse;
	uniform highp sampler2D boneTexture;
	mat4 getBoneMatrix( const in float i ) {
		int size = textureSize( boneTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( boneTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( boneTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( boneTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( boneTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
#endif`,ig=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,rg=`#ifdef USE_SKINNING
	mat4 skinMatrix = mat4( 0.0 );
	skinMatrix += skinWeight.x * boneMatX;
	skinMatrix += skinWeight.y * boneMatY;
	skinMatrix += skinWeight.z * boneMatZ;
	skinMatrix += skinWeight.w * boneMatW;
	skinMatrix = bindMatrixInverse * skinMatrix * bindMatrix;
	objectNormal = vec4( skinMatrix * vec4( objectNormal, 0.0 ) ).xyz;
	#ifdef USE_TANGENT
		objectTangent = vec4( skinMatrix * vec4( objectTangent, 0.0 ) ).xyz;
	#endif
#endif`,sg=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,ag=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,og=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,cg=`#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
uniform float toneMappingExposure;
vec3 LinearToneMapping( vec3 color ) {
	return saturate( toneMappingExposure * color );
}
vec3 ReinhardToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	return saturate( color / ( vec3( 1.0 ) + color ) );
}
vec3 CineonToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	color = max( vec3( 0.0 ), color - 0.004 );
	return pow( ( color * ( 6.2 * color + 0.5 ) ) / ( color * ( 6.2 * color + 1.7 ) + 0.06 ), vec3( 2.2 ) );
}
vec3 RRTAndODTFit( vec3 v ) {
	vec3 a = v * ( v + 0.0245786 ) - 0.000090537;
	vec3 b = v * ( 0.983729 * v + 0.4329510 ) + 0.238081;
	return a / b;
}
vec3 ACESFilmicToneMapping( vec3 color ) {
	const mat3 ACESInputMat = mat3(
		vec3( 0.59719, 0.07600, 0.02840 ),		vec3( 0.35458, 0.90834, 0.13383 ),
		vec3( 0.04823, 0.01566, 0.83777 )
	);
	const mat3 ACESOutputMat = mat3(
		vec3(  1.60475, -0.10208, -0.00327 ),		vec3( -0.53108,  1.10813, -0.07276 ),
		vec3( -0.07367, -0.00605,  1.07602 )
	);
	color *= toneMappingExposure / 0.6;
	color = ACESInputMat * color;
	color = RRTAndODTFit( color );
	color = ACESOutputMat * color;
	return saturate( color );
}
const mat3 LINEAR_REC2020_TO_LINEAR_SRGB = mat3(
	vec3( 1.6605, - 0.1246, - 0.0182 ),
	vec3( - 0.5876, 1.1329, - 0.1006 ),
	vec3( - 0.0728, - 0.0083, 1.1187 )
);
const mat3 LINEAR_SRGB_TO_LINEAR_REC2020 = mat3(
	vec3( 0.6274, 0.0691, 0.0164 ),
	vec3( 0.3293, 0.9195, 0.0880 ),
	vec3( 0.0433, 0.0113, 0.8956 )
);
vec3 agxDefaultContrastApprox( vec3 x ) {
	vec3 x2 = x * x;
	vec3 x4 = x2 * x2;
	return + 15.5 * x4 * x2
		- 40.14 * x4 * x
		+ 31.96 * x4
		- 6.868 * x2 * x
		+ 0.4298 * x2
		+ 0.1191 * x
		- 0.00232;
}
vec3 AgXToneMapping( vec3 color ) {
	const mat3 AgXInsetMatrix = mat3(
		vec3( 0.856627153315983, 0.137318972929847, 0.11189821299995 ),
		vec3( 0.0951212405381588, 0.761241990602591, 0.0767994186031903 ),
		vec3( 0.0482516061458583, 0.101439036467562, 0.811302368396859 )
	);
	const mat3 AgXOutsetMatrix = mat3(
		vec3( 1.1271005818144368, - 0.1413297634984383, - 0.14132976349843826 ),
		vec3( - 0.11060664309660323, 1.157823702216272, - 0.11060664309660294 ),
		vec3( - 0.016493938717834573, - 0.016493938717834257, 1.2519364065950405 )
	);
	const float AgxMinEv = - 12.47393;	const float AgxMaxEv = 4.026069;
	color *= toneMappingExposure;
	color = LINEAR_SRGB_TO_LINEAR_REC2020 * color;
	color = AgXInsetMatrix * color;
	color = max( color, 1e-10 );	color = log2( color );
	color = ( color - AgxMinEv ) / ( AgxMaxEv - AgxMinEv );
	color = clamp( color, 0.0, 1.0 );
	color = agxDefaultContrastApprox( color );
	color = AgXOutsetMatrix * color;
	color = pow( max( vec3( 0.0 ), color ), vec3( 2.2 ) );
	color = LINEAR_REC2020_TO_LINEAR_SRGB * color;
	color = clamp( color, 0.0, 1.0 );
	return color;
}
vec3 NeutralToneMapping( vec3 color ) {
	const float StartCompression = 0.8 - 0.04;
	const float Desaturation = 0.15;
	color *= toneMappingExposure;
	float x = min( color.r, min( color.g, color.b ) );
	float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
	color -= offset;
	float peak = max( color.r, max( color.g, color.b ) );
	if ( peak < StartCompression ) return color;
	float d = 1. - StartCompression;
	float newPeak = 1. - d * d / ( peak + d - StartCompression );
	color *= newPeak / peak;
	float g = 1. - 1. / ( Desaturation * ( peak - newPeak ) + 1. );
	return mix( color, vec3( newPeak ), g );
}
vec3 CustomToneMapping( vec3 color ) { return color; }`,lg=`#ifdef USE_TRANSMISSION
	material.transmission = transmission;
	material.transmissionAlpha = 1.0;
	material.thickness = thickness;
	material.attenuationDistance = attenuationDistance;
	material.attenuationColor = attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		material.transmission *= texture2D( transmissionMap, vTransmissionMapUv ).r;
	#endif
	#ifdef USE_THICKNESSMAP
		material.thickness *= texture2D( thicknessMap, vThicknessMapUv ).g;
	#endif
	vec3 pos = vWorldPosition;
	vec3 v = normalize( cameraPosition - pos );
	vec3 n = inverseTransformDirection( normal, viewMatrix );
	vec4 transmitted = getIBLVolumeRefraction(
		n, v, material.roughness, material.diffuseColor, material.specularColor, material.specularF90,
		pos, modelMatrix, viewMatrix, projectionMatrix, material.dispersion, material.ior, material.thickness,
		material.attenuationColor, material.attenuationDistance );
	material.transmissionAlpha = mix( material.transmissionAlpha, transmitted.a, material.transmission );
	totalDiffuse = mix( totalDiffuse, transmitted.rgb, material.transmission );
#endif`,hg=`#ifdef USE_TRANSMISSION
	uniform float transmission;
	uniform float thickness;
	uniform float attenuationDistance;
	uniform vec3 attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		uniform sampler2D transmissionMap;
	#endif
	#ifdef USE_THICKNESSMAP
		uniform sampler2D thicknessMap;
	#endif
	uniform vec2 transmissionSamplerSize;
	uniform sampler2D transmissionSamplerMap;
	uniform mat4 modelMatrix;
	uniform mat4 projectionMatrix;
	varying vec3 vWorldPosition;
	float w0( float a ) {
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - a + 3.0 ) - 3.0 ) + 1.0 );
	}
	float w1( float a ) {
		return ( 1.0 / 6.0 ) * ( a *  a * ( 3.0 * a - 6.0 ) + 4.0 );
	}
	float w2( float a ){
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - 3.0 * a + 3.0 ) + 3.0 ) + 1.0 );
	}
	float w3( float a ) {
		return ( 1.0 / 6.0 ) * ( a * a * a );
	}
	float g0( float a ) {
		return w0( a ) + w1( a );
	}
	float g1( float a ) {
		return w2( a ) + w3( a );
	}
	float h0( float a ) {
		return - 1.0 + w1( a ) / ( w0( a ) + w1( a ) );
	}
	float h1( float a ) {
		return 1.0 + w3( a ) / ( w2( a ) + w3( a ) );
	}
	vec4 bicubic( sampler2D tex, vec2 uv, vec4 texelSize, float lod ) {
		uv = uv * texelSize.zw + 0.5;
		vec2 iuv = floor( uv );
		vec2 fuv = fract( uv );
		float g0x = g0( fuv.x );
		float g1x = g1( fuv.x );
		float h0x = h0( fuv.x );
		float h1x = h1( fuv.x );
		float h0y = h0( fuv.y );
		float h1y = h1( fuv.y );
		vec2 p0 = ( vec2( iuv.x + h0x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p1 = ( vec2( iuv.x + h1x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p2 = ( vec2( iuv.x + h0x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		vec2 p3 = ( vec2( iuv.x + h1x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		return g0( fuv.y ) * ( g0x * textureLod( tex, p0, lod ) + g1x * textureLod( tex, p1, lod ) ) +
			g1( fuv.y ) * ( g0x * textureLod( tex, p2, lod ) + g1x * textureLod( tex, p3, lod ) );
	}
	vec4 textureBicubic( sampler2D sampler, vec2 uv, float lod ) {
		vec2 fLodSize = vec2( textureSize( sampler, int( lod ) ) );
		vec2 cLodSize = vec2( textureSize( sampler, int( lod + 1.0 ) ) );
		vec2 fLodSizeInv = 1.0 / fLodSize;
		vec2 cLodSizeInv = 1.0 / cLodSize;
		vec4 fSample = bicubic( sampler, uv, vec4( fLodSizeInv, fLodSize ), floor( lod ) );
		vec4 cSample = bicubic( sampler, uv, vec4( cLodSizeInv, cLodSize ), ceil( lod ) );
		return mix( fSample, cSample, fract( lod ) );
	}
	vec3 getVolumeTransmissionRay( const in vec3 n, const in vec3 v, const in float thickness, const in float ior, const in mat4 modelMatrix ) {
		vec3 refractionVector = refract( - v, normalize( n ), 1.0 / ior );
		vec3 modelScale;
		modelScale.x = length( vec3( modelMatrix[ 0 ].xyz ) );
		modelScale.y = length( vec3( modelMatrix[ 1 ].xyz ) );
		modelScale.z = length( vec3( modelMatrix[ 2 ].xyz ) );
		return normalize( refractionVector ) * thickness * modelScale;
	}
	float applyIorToRoughness( const in float roughness, const in float ior ) {
		return roughness * clamp( ior * 2.0 - 2.0, 0.0, 1.0 );
	}
	vec4 getTransmissionSample( const in vec2 fragCoord, const in float roughness, const in float ior ) {
		float lod = log2( transmissionSamplerSize.x ) * applyIorToRoughness( roughness, ior );
		return textureBicubic( transmissionSamplerMap, fragCoord.xy, lod );
	}
	vec3 volumeAttenuation( const in float transmissionDistance, const in vec3 attenuationColor, const in float attenuationDistance ) {
		if ( isinf( attenuationDistance ) ) {
			return vec3( 1.0 );
		} else {
			vec3 attenuationCoefficient = -log( attenuationColor ) / attenuationDistance;
			vec3 transmittance = exp( - attenuationCoefficient * transmissionDistance );			return transmittance;
		}
	}
	vec4 getIBLVolumeRefraction( const in vec3 n, const in vec3 v, const in float roughness, const in vec3 diffuseColor,
		const in vec3 specularColor, const in float specularF90, const in vec3 position, const in mat4 modelMatrix,
		const in mat4 viewMatrix, const in mat4 projMatrix, const in float dispersion, const in float ior, const in float thickness,
		const in vec3 attenuationColor, const in float attenuationDistance ) {
		vec4 transmittedLight;
		vec3 transmittance;
		#ifdef USE_DISPERSION
			float halfSpread = ( ior - 1.0 ) * 0.025 * dispersion;
			vec3 iors = vec3( ior - halfSpread, ior, ior + halfSpread );
			for ( int i = 0; i < 3; i ++ ) {
				vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, iors[ i ], modelMatrix );
				vec3 refractedRayExit = position + transmissionRay;
		
				vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
				vec2 refractionCoords = ndcPos.xy / ndcPos.w;
				refractionCoords += 1.0;
				refractionCoords /= 2.0;
		
				vec4 transmissionSample = getTransmissionSample( refractionCoords, roughness, iors[ i ] );
				transmittedLight[ i ] = transmissionSample[ i ];
				transmittedLight.a += transmissionSample.a;
				transmittance[ i ] = diffuseColor[ i ] * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance )[ i ];
			}
			transmittedLight.a /= 3.0;
		
		#else
		
			vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, ior, modelMatrix );
			vec3 refractedRayExit = position + transmissionRay;
			vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
			vec2 refractionCoords = ndcPos.xy / ndcPos.w;
			refractionCoords += 1.0;
			refractionCoords /= 2.0;
			transmittedLight = getTransmissionSample( refractionCoords, roughness, ior );
			transmittance = diffuseColor * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance );
		
		#endif
		vec3 attenuatedColor = transmittance * transmittedLight.rgb;
		vec3 F = EnvironmentBRDF( n, v, specularColor, specularF90, roughness );
		float transmittanceFactor = ( transmittance.r + transmittance.g + transmittance.b ) / 3.0;
		return vec4( ( 1.0 - F ) * attenuatedColor, 1.0 - ( 1.0 - transmittedLight.a ) * transmittanceFactor );
	}
#endif`,ug=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_SPECULARMAP
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,dg=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	uniform mat3 mapTransform;
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	uniform mat3 alphaMapTransform;
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	uniform mat3 lightMapTransform;
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	uniform mat3 aoMapTransform;
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	uniform mat3 bumpMapTransform;
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	uniform mat3 normalMapTransform;
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_DISPLACEMENTMAP
	uniform mat3 displacementMapTransform;
	varying vec2 vDisplacementMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	uniform mat3 emissiveMapTransform;
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	uniform mat3 metalnessMapTransform;
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	uniform mat3 roughnessMapTransform;
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	uniform mat3 anisotropyMapTransform;
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	uniform mat3 clearcoatMapTransform;
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform mat3 clearcoatNormalMapTransform;
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform mat3 clearcoatRoughnessMapTransform;
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	uniform mat3 sheenColorMapTransform;
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	uniform mat3 sheenRoughnessMapTransform;
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	uniform mat3 iridescenceMapTransform;
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform mat3 iridescenceThicknessMapTransform;
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SPECULARMAP
	uniform mat3 specularMapTransform;
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	uniform mat3 specularColorMapTransform;
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	uniform mat3 specularIntensityMapTransform;
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,fg=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	vUv = vec3( uv, 1 ).xy;
#endif
#ifdef USE_MAP
	vMapUv = ( mapTransform * vec3( MAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ALPHAMAP
	vAlphaMapUv = ( alphaMapTransform * vec3( ALPHAMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_LIGHTMAP
	vLightMapUv = ( lightMapTransform * vec3( LIGHTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_AOMAP
	vAoMapUv = ( aoMapTransform * vec3( AOMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_BUMPMAP
	vBumpMapUv = ( bumpMapTransform * vec3( BUMPMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_NORMALMAP
	vNormalMapUv = ( normalMapTransform * vec3( NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DISPLACEMENTMAP
	vDisplacementMapUv = ( displacementMapTransform * vec3( DISPLACEMENTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_EMISSIVEMAP
	vEmissiveMapUv = ( emissiveMapTransform * vec3( EMISSIVEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_METALNESSMAP
	vMetalnessMapUv = ( metalnessMapTransform * vec3( METALNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ROUGHNESSMAP
	vRoughnessMapUv = ( roughnessMapTransform * vec3( ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ANISOTROPYMAP
	vAnisotropyMapUv = ( anisotropyMapTransform * vec3( ANISOTROPYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOATMAP
	vClearcoatMapUv = ( clearcoatMapTransform * vec3( CLEARCOATMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	vClearcoatNormalMapUv = ( clearcoatNormalMapTransform * vec3( CLEARCOAT_NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	vClearcoatRoughnessMapUv = ( clearcoatRoughnessMapTransform * vec3( CLEARCOAT_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCEMAP
	vIridescenceMapUv = ( iridescenceMapTransform * vec3( IRIDESCENCEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	vIridescenceThicknessMapUv = ( iridescenceThicknessMapTransform * vec3( IRIDESCENCE_THICKNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_COLORMAP
	vSheenColorMapUv = ( sheenColorMapTransform * vec3( SHEEN_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	vSheenRoughnessMapUv = ( sheenRoughnessMapTransform * vec3( SHEEN_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULARMAP
	vSpecularMapUv = ( specularMapTransform * vec3( SPECULARMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_COLORMAP
	vSpecularColorMapUv = ( specularColorMapTransform * vec3( SPECULAR_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	vSpecularIntensityMapUv = ( specularIntensityMapTransform * vec3( SPECULAR_INTENSITYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_TRANSMISSIONMAP
	vTransmissionMapUv = ( transmissionMapTransform * vec3( TRANSMISSIONMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_THICKNESSMAP
	vThicknessMapUv = ( thicknessMapTransform * vec3( THICKNESSMAP_UV, 1 ) ).xy;
#endif`,pg=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`,mg=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,gg=`uniform sampler2D t2D;
uniform float backgroundIntensity;
varying vec2 vUv;
void main() {
	vec4 texColor = texture2D( t2D, vUv );
	#ifdef DECODE_VIDEO_TEXTURE
		texColor = vec4( mix( pow( texColor.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), texColor.rgb * 0.0773993808, vec3( lessThanEqual( texColor.rgb, vec3( 0.04045 ) ) ) ), texColor.w );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,vg=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,_g=`#ifdef ENVMAP_TYPE_CUBE
	uniform samplerCube envMap;
#elif defined( ENVMAP_TYPE_CUBE_UV )
	uniform sampler2D envMap;
#endif
uniform float flipEnvMap;
uniform float backgroundBlurriness;
uniform float backgroundIntensity;
uniform mat3 backgroundRotation;
varying vec3 vWorldDirection;
#include <cube_uv_reflection_fragment>
void main() {
	#ifdef ENVMAP_TYPE_CUBE
		vec4 texColor = textureCube( envMap, backgroundRotation * vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) );
	#elif defined( ENVMAP_TYPE_CUBE_UV )
		vec4 texColor = textureCubeUV( envMap, backgroundRotation * vWorldDirection, backgroundBlurriness );
	#else
		vec4 texColor = vec4( 0.0, 0.0, 0.0, 1.0 );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,yg=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,xg=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,bg=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
varying vec2 vHighPrecisionZW;
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vHighPrecisionZW = gl_Position.zw;
}`,Sg=`#if DEPTH_PACKING == 3200
	uniform float opacity;
#endif
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
varying vec2 vHighPrecisionZW;
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#if DEPTH_PACKING == 3200
		diffuseColor.a = opacity;
	#endif
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <logdepthbuf_fragment>
	float fragCoordZ = 0.5 * vHighPrecisionZW[0] / vHighPrecisionZW[1] + 0.5;
	#if DEPTH_PACKING == 3200
		gl_FragColor = vec4( vec3( 1.0 - fragCoordZ ), opacity );
	#elif DEPTH_PACKING == 3201
		gl_FragColor = packDepthToRGBA( fragCoordZ );
	#elif DEPTH_PACKING == 3202
		gl_FragColor = vec4( packDepthToRGB( fragCoordZ ), 1.0 );
	#elif DEPTH_PACKING == 3203
		gl_FragColor = vec4( packDepthToRG( fragCoordZ ), 0.0, 1.0 );
	#endif
}`,Mg=`#define DISTANCE
varying vec3 vWorldPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <worldpos_vertex>
	#include <clipping_planes_vertex>
	vWorldPosition = worldPosition.xyz;
}`,wg=`#define DISTANCE
uniform vec3 referencePosition;
uniform float nearDistance;
uniform float farDistance;
varying vec3 vWorldPosition;
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <clipping_planes_pars_fragment>
void main () {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	float dist = length( vWorldPosition - referencePosition );
	dist = ( dist - nearDistance ) / ( farDistance - nearDistance );
	dist = saturate( dist );
	gl_FragColor = packDepthToRGBA( dist );
}`,Eg=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,Tg=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Ag=`uniform float scale;
attribute float lineDistance;
varying float vLineDistance;
#include <common>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	vLineDistance = scale * lineDistance;
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,Cg=`uniform vec3 diffuse;
uniform float opacity;
uniform float dashSize;
uniform float totalSize;
varying float vLineDistance;
#include <common>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	if ( mod( vLineDistance, totalSize ) > dashSize ) {
		discard;
	}
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,Rg=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#if defined ( USE_ENVMAP ) || defined ( USE_SKINNING )
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinbase_vertex>
		#include <skinnormal_vertex>
		#include <defaultnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <fog_vertex>
}`,Pg=`uniform vec3 diffuse;
uniform float opacity;
#ifndef FLAT_SHADED
	varying vec3 vNormal;
#endif
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		reflectedLight.indirectDiffuse += lightMapTexel.rgb * lightMapIntensity * RECIPROCAL_PI;
	#else
		reflectedLight.indirectDiffuse += vec3( 1.0 );
	#endif
	#include <aomap_fragment>
	reflectedLight.indirectDiffuse *= diffuseColor.rgb;
	vec3 outgoingLight = reflectedLight.indirectDiffuse;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,Lg=`#define LAMBERT
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,Ig=`#define LAMBERT
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <packing>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_lambert_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_lambert_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,Dg=`#define MATCAP
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <displacementmap_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
	vViewPosition = - mvPosition.xyz;
}`,Ng=`#define MATCAP
uniform vec3 diffuse;
uniform float opacity;
uniform sampler2D matcap;
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	vec3 viewDir = normalize( vViewPosition );
	vec3 x = normalize( vec3( viewDir.z, 0.0, - viewDir.x ) );
	vec3 y = cross( viewDir, x );
	vec2 uv = vec2( dot( x, normal ), dot( y, normal ) ) * 0.495 + 0.5;
	#ifdef USE_MATCAP
		vec4 matcapColor = texture2D( matcap, uv );
	#else
		vec4 matcapColor = vec4( vec3( mix( 0.2, 0.8, uv.y ) ), 1.0 );
	#endif
	vec3 outgoingLight = diffuseColor.rgb * matcapColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,Ug=`#define NORMAL
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	vViewPosition = - mvPosition.xyz;
#endif
}`,Fg=`#define NORMAL
uniform float opacity;
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <packing>
#include <uv_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 0.0, 0.0, 0.0, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	gl_FragColor = vec4( packNormalToRGB( normal ), diffuseColor.a );
	#ifdef OPAQUE
		gl_FragColor.a = 1.0;
	#endif
}`,Og=`#define PHONG
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,kg=`#define PHONG
uniform vec3 diffuse;
uniform vec3 emissive;
uniform vec3 specular;
uniform float shininess;
uniform float opacity;
#include <common>
#include <packing>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_phong_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_phong_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + reflectedLight.directSpecular + reflectedLight.indirectSpecular + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,Bg=`#define STANDARD
varying vec3 vViewPosition;
#ifdef USE_TRANSMISSION
	varying vec3 vWorldPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
#ifdef USE_TRANSMISSION
	vWorldPosition = worldPosition.xyz;
#endif
}`,zg=`#define STANDARD
#ifdef PHYSICAL
	#define IOR
	#define USE_SPECULAR
#endif
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float roughness;
uniform float metalness;
uniform float opacity;
#ifdef IOR
	uniform float ior;
#endif
#ifdef USE_SPECULAR
	uniform float specularIntensity;
	uniform vec3 specularColor;
	#ifdef USE_SPECULAR_COLORMAP
		uniform sampler2D specularColorMap;
	#endif
	#ifdef USE_SPECULAR_INTENSITYMAP
		uniform sampler2D specularIntensityMap;
	#endif
#endif
#ifdef USE_CLEARCOAT
	uniform float clearcoat;
	uniform float clearcoatRoughness;
#endif
#ifdef USE_DISPERSION
	uniform float dispersion;
#endif
#ifdef USE_IRIDESCENCE
	uniform float iridescence;
	uniform float iridescenceIOR;
	uniform float iridescenceThicknessMinimum;
	uniform float iridescenceThicknessMaximum;
#endif
#ifdef USE_SHEEN
	uniform vec3 sheenColor;
	uniform float sheenRoughness;
	#ifdef USE_SHEEN_COLORMAP
		uniform sampler2D sheenColorMap;
	#endif
	#ifdef USE_SHEEN_ROUGHNESSMAP
		uniform sampler2D sheenRoughnessMap;
	#endif
#endif
#ifdef USE_ANISOTROPY
	uniform vec2 anisotropyVector;
	#ifdef USE_ANISOTROPYMAP
		uniform sampler2D anisotropyMap;
	#endif
#endif
varying vec3 vViewPosition;
#include <common>
#include <packing>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <iridescence_fragment>
#include <cube_uv_reflection_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_physical_pars_fragment>
#include <transmission_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <clearcoat_pars_fragment>
#include <iridescence_pars_fragment>
#include <roughnessmap_pars_fragment>
#include <metalnessmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <roughnessmap_fragment>
	#include <metalnessmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <clearcoat_normal_fragment_begin>
	#include <clearcoat_normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_physical_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 totalDiffuse = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse;
	vec3 totalSpecular = reflectedLight.directSpecular + reflectedLight.indirectSpecular;
	#include <transmission_fragment>
	vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;
	#ifdef USE_SHEEN
		float sheenEnergyComp = 1.0 - 0.157 * max3( material.sheenColor );
		outgoingLight = outgoingLight * sheenEnergyComp + sheenSpecularDirect + sheenSpecularIndirect;
	#endif
	#ifdef USE_CLEARCOAT
		float dotNVcc = saturate( dot( geometryClearcoatNormal, geometryViewDir ) );
		vec3 Fcc = F_Schlick( material.clearcoatF0, material.clearcoatF90, dotNVcc );
		outgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + clearcoatSpecularIndirect ) * material.clearcoat;
	#endif
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,Gg=`#define TOON
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,Vg=`#define TOON
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <packing>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <gradientmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_toon_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_toon_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,Hg=`uniform float size;
uniform float scale;
#include <common>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
#ifdef USE_POINTS_UV
	varying vec2 vUv;
	uniform mat3 uvTransform;
#endif
void main() {
	#ifdef USE_POINTS_UV
		vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	#endif
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	gl_PointSize = size;
	#ifdef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) gl_PointSize *= ( scale / - mvPosition.z );
	#endif
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <fog_vertex>
}`,Wg=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <color_pars_fragment>
#include <map_particle_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_particle_fragment>
	#include <color_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,Xg=`#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <shadowmap_pars_vertex>
void main() {
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,qg=`uniform vec3 color;
uniform float opacity;
#include <common>
#include <packing>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <logdepthbuf_pars_fragment>
#include <shadowmap_pars_fragment>
#include <shadowmask_pars_fragment>
void main() {
	#include <logdepthbuf_fragment>
	gl_FragColor = vec4( color, opacity * ( 1.0 - getShadowMask() ) );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,Yg=`uniform float rotation;
uniform vec2 center;
#include <common>
#include <uv_pars_vertex>
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	vec4 mvPosition = modelViewMatrix[ 3 ];
	vec2 scale = vec2( length( modelMatrix[ 0 ].xyz ), length( modelMatrix[ 1 ].xyz ) );
	#ifndef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) scale *= - mvPosition.z;
	#endif
	vec2 alignedPosition = ( position.xy - ( center - vec2( 0.5 ) ) ) * scale;
	vec2 rotatedPosition;
	rotatedPosition.x = cos( rotation ) * alignedPosition.x - sin( rotation ) * alignedPosition.y;
	rotatedPosition.y = sin( rotation ) * alignedPosition.x + cos( rotation ) * alignedPosition.y;
	mvPosition.xy += rotatedPosition;
	gl_Position = projectionMatrix * mvPosition;
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,Zg=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,Ye={alphahash_fragment:gp,alphahash_pars_fragment:vp,alphamap_fragment:_p,alphamap_pars_fragment:yp,alphatest_fragment:xp,alphatest_pars_fragment:bp,aomap_fragment:Sp,aomap_pars_fragment:Mp,batching_pars_vertex:wp,batching_vertex:Ep,begin_vertex:Tp,beginnormal_vertex:Ap,bsdfs:Cp,iridescence_fragment:Rp,bumpmap_pars_fragment:Pp,clipping_planes_fragment:Lp,clipping_planes_pars_fragment:Ip,clipping_planes_pars_vertex:Dp,clipping_planes_vertex:Np,color_fragment:Up,color_pars_fragment:Fp,color_pars_vertex:Op,color_vertex:kp,common:Bp,cube_uv_reflection_fragment:zp,defaultnormal_vertex:Gp,displacementmap_pars_vertex:Vp,displacementmap_vertex:Hp,emissivemap_fragment:Wp,emissivemap_pars_fragment:Xp,colorspace_fragment:qp,colorspace_pars_fragment:Yp,envmap_fragment:Zp,envmap_common_pars_fragment:$p,envmap_pars_fragment:Kp,envmap_pars_vertex:jp,envmap_physical_pars_fragment:cm,envmap_vertex:Jp,fog_vertex:Qp,fog_pars_vertex:em,fog_fragment:tm,fog_pars_fragment:nm,gradientmap_pars_fragment:im,lightmap_pars_fragment:rm,lights_lambert_fragment:sm,lights_lambert_pars_fragment:am,lights_pars_begin:om,lights_toon_fragment:lm,lights_toon_pars_fragment:hm,lights_phong_fragment:um,lights_phong_pars_fragment:dm,lights_physical_fragment:fm,lights_physical_pars_fragment:pm,lights_fragment_begin:mm,lights_fragment_maps:gm,lights_fragment_end:vm,logdepthbuf_fragment:_m,logdepthbuf_pars_fragment:ym,logdepthbuf_pars_vertex:xm,logdepthbuf_vertex:bm,map_fragment:Sm,map_pars_fragment:Mm,map_particle_fragment:wm,map_particle_pars_fragment:Em,metalnessmap_fragment:Tm,metalnessmap_pars_fragment:Am,morphinstance_vertex:Cm,morphcolor_vertex:Rm,morphnormal_vertex:Pm,morphtarget_pars_vertex:Lm,morphtarget_vertex:Im,normal_fragment_begin:Dm,normal_fragment_maps:Nm,normal_pars_fragment:Um,normal_pars_vertex:Fm,normal_vertex:Om,normalmap_pars_fragment:km,clearcoat_normal_fragment_begin:Bm,clearcoat_normal_fragment_maps:zm,clearcoat_pars_fragment:Gm,iridescence_pars_fragment:Vm,opaque_fragment:Hm,packing:Wm,premultiplied_alpha_fragment:Xm,project_vertex:qm,dithering_fragment:Ym,dithering_pars_fragment:Zm,roughnessmap_fragment:$m,roughnessmap_pars_fragment:Km,shadowmap_pars_fragment:jm,shadowmap_pars_vertex:Jm,shadowmap_vertex:Qm,shadowmask_pars_fragment:eg,skinbase_vertex:tg,skinning_pars_vertex:ng,skinning_vertex:ig,skinnormal_vertex:rg,specularmap_fragment:sg,specularmap_pars_fragment:ag,tonemapping_fragment:og,tonemapping_pars_fragment:cg,transmission_fragment:lg,transmission_pars_fragment:hg,uv_pars_fragment:ug,uv_pars_vertex:dg,uv_vertex:fg,worldpos_vertex:pg,background_vert:mg,background_frag:gg,backgroundCube_vert:vg,backgroundCube_frag:_g,cube_vert:yg,cube_frag:xg,depth_vert:bg,depth_frag:Sg,distanceRGBA_vert:Mg,distanceRGBA_frag:wg,equirect_vert:Eg,equirect_frag:Tg,linedashed_vert:Ag,linedashed_frag:Cg,meshbasic_vert:Rg,meshbasic_frag:Pg,meshlambert_vert:Lg,meshlambert_frag:Ig,meshmatcap_vert:Dg,meshmatcap_frag:Ng,meshnormal_vert:Ug,meshnormal_frag:Fg,meshphong_vert:Og,meshphong_frag:kg,meshphysical_vert:Bg,meshphysical_frag:zg,meshtoon_vert:Gg,meshtoon_frag:Vg,points_vert:Hg,points_frag:Wg,shadow_vert:Xg,shadow_frag:qg,sprite_vert:Yg,sprite_frag:Zg},ye={common:{diffuse:{value:new tt(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new He},alphaMap:{value:null},alphaMapTransform:{value:new He},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new He}},envmap:{envMap:{value:null},envMapRotation:{value:new He},flipEnvMap:{value:-1},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new He}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new He}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new He},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new He},normalScale:{value:new $e(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new He},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new He}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new He}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new He}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new tt(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMap:{value:[]},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotShadowMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMap:{value:[]},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null}},points:{diffuse:{value:new tt(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new He},alphaTest:{value:0},uvTransform:{value:new He}},sprite:{diffuse:{value:new tt(16777215)},opacity:{value:1},center:{value:new $e(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new He},alphaMap:{value:null},alphaMapTransform:{value:new He},alphaTest:{value:0}}},dn={basic:{uniforms:Dt([ye.common,ye.specularmap,ye.envmap,ye.aomap,ye.lightmap,ye.fog]),vertexShader:Ye.meshbasic_vert,fragmentShader:Ye.meshbasic_frag},lambert:{uniforms:Dt([ye.common,ye.specularmap,ye.envmap,ye.aomap,ye.lightmap,ye.emissivemap,ye.bumpmap,ye.normalmap,ye.displacementmap,ye.fog,ye.lights,{emissive:{value:new tt(0)}}]),vertexShader:Ye.meshlambert_vert,fragmentShader:Ye.meshlambert_frag},phong:{uniforms:Dt([ye.common,ye.specularmap,ye.envmap,ye.aomap,ye.lightmap,ye.emissivemap,ye.bumpmap,ye.normalmap,ye.displacementmap,ye.fog,ye.lights,{emissive:{value:new tt(0)},specular:{value:new tt(1118481)},shininess:{value:30}}]),vertexShader:Ye.meshphong_vert,fragmentShader:Ye.meshphong_frag},standard:{uniforms:Dt([ye.common,ye.envmap,ye.aomap,ye.lightmap,ye.emissivemap,ye.bumpmap,ye.normalmap,ye.displacementmap,ye.roughnessmap,ye.metalnessmap,ye.fog,ye.lights,{emissive:{value:new tt(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:Ye.meshphysical_vert,fragmentShader:Ye.meshphysical_frag},toon:{uniforms:Dt([ye.common,ye.aomap,ye.lightmap,ye.emissivemap,ye.bumpmap,ye.normalmap,ye.displacementmap,ye.gradientmap,ye.fog,ye.lights,{emissive:{value:new tt(0)}}]),vertexShader:Ye.meshtoon_vert,fragmentShader:Ye.meshtoon_frag},matcap:{uniforms:Dt([ye.common,ye.bumpmap,ye.normalmap,ye.displacementmap,ye.fog,{matcap:{value:null}}]),vertexShader:Ye.meshmatcap_vert,fragmentShader:Ye.meshmatcap_frag},points:{uniforms:Dt([ye.points,ye.fog]),vertexShader:Ye.points_vert,fragmentShader:Ye.points_frag},dashed:{uniforms:Dt([ye.common,ye.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:Ye.linedashed_vert,fragmentShader:Ye.linedashed_frag},depth:{uniforms:Dt([ye.common,ye.displacementmap]),vertexShader:Ye.depth_vert,fragmentShader:Ye.depth_frag},normal:{uniforms:Dt([ye.common,ye.bumpmap,ye.normalmap,ye.displacementmap,{opacity:{value:1}}]),vertexShader:Ye.meshnormal_vert,fragmentShader:Ye.meshnormal_frag},sprite:{uniforms:Dt([ye.sprite,ye.fog]),vertexShader:Ye.sprite_vert,fragmentShader:Ye.sprite_frag},background:{uniforms:{uvTransform:{value:new He},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:Ye.background_vert,fragmentShader:Ye.background_frag},backgroundCube:{uniforms:{envMap:{value:null},flipEnvMap:{value:-1},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new He}},vertexShader:Ye.backgroundCube_vert,fragmentShader:Ye.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:Ye.cube_vert,fragmentShader:Ye.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:Ye.equirect_vert,fragmentShader:Ye.equirect_frag},distanceRGBA:{uniforms:Dt([ye.common,ye.displacementmap,{referencePosition:{value:new X},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:Ye.distanceRGBA_vert,fragmentShader:Ye.distanceRGBA_frag},shadow:{uniforms:Dt([ye.lights,ye.fog,{color:{value:new tt(0)},opacity:{value:1}}]),vertexShader:Ye.shadow_vert,fragmentShader:Ye.shadow_frag}};dn.physical={uniforms:Dt([dn.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new He},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new He},clearcoatNormalScale:{value:new $e(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new He},dispersion:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new He},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new He},sheen:{value:0},sheenColor:{value:new tt(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new He},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new He},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new He},transmissionSamplerSize:{value:new $e},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new He},attenuationDistance:{value:0},attenuationColor:{value:new tt(0)},specularColor:{value:new tt(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new He},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new He},anisotropyVector:{value:new $e},anisotropyMap:{value:null},anisotropyMapTransform:{value:new He}}]),vertexShader:Ye.meshphysical_vert,fragmentShader:Ye.meshphysical_frag};var ds={r:0,b:0,g:0},oi=new Dn,$g=new _t;function Kg(i,e,t,n,r,s,a){let o=new tt(0),l=s===!0?0:1,h,d,m=null,f=0,v=null;function S(I){let P=I.isScene===!0?I.background:null;return P&&P.isTexture&&(P=(I.backgroundBlurriness>0?t:e).get(P)),P}function E(I){let P=!1,C=S(I);C===null?g(o,l):C&&C.isColor&&(g(C,1),P=!0);let H=i.xr.getEnvironmentBlendMode();H==="additive"?n.buffers.color.setClear(0,0,0,1,a):H==="alpha-blend"&&n.buffers.color.setClear(0,0,0,0,a),(i.autoClear||P)&&(n.buffers.depth.setTest(!0),n.buffers.depth.setMask(!0),n.buffers.color.setMask(!0),i.clear(i.autoClearColor,i.autoClearDepth,i.autoClearStencil))}function _(I,P){let C=S(P);C&&(C.isCubeTexture||C.mapping===Hs)?(d===void 0&&(d=new an(new Rr(1,1,1),new mn({name:"BackgroundCubeMaterial",uniforms:tr(dn.backgroundCube.uniforms),vertexShader:dn.backgroundCube.vertexShader,fragmentShader:dn.backgroundCube.fragmentShader,side:kt,depthTest:!1,depthWrite:!1,fog:!1})),d.geometry.deleteAttribute("normal"),d.geometry.deleteAttribute("uv"),d.onBeforeRender=function(H,U,N){this.matrixWorld.copyPosition(N.matrixWorld)},Object.defineProperty(d.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),r.update(d)),oi.copy(P.backgroundRotation),oi.x*=-1,oi.y*=-1,oi.z*=-1,C.isCubeTexture&&C.isRenderTargetTexture===!1&&(oi.y*=-1,oi.z*=-1),d.material.uniforms.envMap.value=C,d.material.uniforms.flipEnvMap.value=C.isCubeTexture&&C.isRenderTargetTexture===!1?-1:1,d.material.uniforms.backgroundBlurriness.value=P.backgroundBlurriness,d.material.uniforms.backgroundIntensity.value=P.backgroundIntensity,d.material.uniforms.backgroundRotation.value.setFromMatrix4($g.makeRotationFromEuler(oi)),d.material.toneMapped=et.getTransfer(C.colorSpace)!==ct,(m!==C||f!==C.version||v!==i.toneMapping)&&(d.material.needsUpdate=!0,m=C,f=C.version,v=i.toneMapping),d.layers.enableAll(),I.unshift(d,d.geometry,d.material,0,0,null)):C&&C.isTexture&&(h===void 0&&(h=new an(new Us(2,2),new mn({name:"BackgroundMaterial",uniforms:tr(dn.background.uniforms),vertexShader:dn.background.vertexShader,fragmentShader:dn.background.fragmentShader,side:Kn,depthTest:!1,depthWrite:!1,fog:!1})),h.geometry.deleteAttribute("normal"),Object.defineProperty(h.material,"map",{get:function(){return this.uniforms.t2D.value}}),r.update(h)),h.material.uniforms.t2D.value=C,h.material.uniforms.backgroundIntensity.value=P.backgroundIntensity,h.material.toneMapped=et.getTransfer(C.colorSpace)!==ct,C.matrixAutoUpdate===!0&&C.updateMatrix(),h.material.uniforms.uvTransform.value.copy(C.matrix),(m!==C||f!==C.version||v!==i.toneMapping)&&(h.material.needsUpdate=!0,m=C,f=C.version,v=i.toneMapping),h.layers.enableAll(),I.unshift(h,h.geometry,h.material,0,0,null))}function g(I,P){I.getRGB(ds,tu(i)),n.buffers.color.setClear(ds.r,ds.g,ds.b,P,a)}return{getClearColor:function(){return o},setClearColor:function(I,P=1){o.set(I),l=P,g(o,l)},getClearAlpha:function(){return l},setClearAlpha:function(I){l=I,g(o,l)},render:E,addToRenderList:_}}function jg(i,e){let t=i.getParameter(i.MAX_VERTEX_ATTRIBS),n={},r=f(null),s=r,a=!1;function o(R,F,Q,Z,J){let ie=!1,$=m(Z,Q,F);s!==$&&(s=$,h(s.object)),ie=v(R,Z,Q,J),ie&&S(R,Z,Q,J),J!==null&&e.update(J,i.ELEMENT_ARRAY_BUFFER),(ie||a)&&(a=!1,C(R,F,Q,Z),J!==null&&i.bindBuffer(i.ELEMENT_ARRAY_BUFFER,e.get(J).buffer))}function l(){return i.createVertexArray()}function h(R){return i.bindVertexArray(R)}function d(R){return i.deleteVertexArray(R)}function m(R,F,Q){let Z=Q.wireframe===!0,J=n[R.id];J===void 0&&(J={},n[R.id]=J);let ie=J[F.id];ie===void 0&&(ie={},J[F.id]=ie);let $=ie[Z];return $===void 0&&($=f(l()),ie[Z]=$),$}function f(R){let F=[],Q=[],Z=[];for(let J=0;J<t;J++)F[J]=0,Q[J]=0,Z[J]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:F,enabledAttributes:Q,attributeDivisors:Z,object:R,attributes:{},index:null}}function v(R,F,Q,Z){let J=s.attributes,ie=F.attributes,$=0,ue=Q.getAttributes();for(let j in ue)if(ue[j].location>=0){let _e=J[j],Ce=ie[j];if(Ce===void 0&&(j==="instanceMatrix"&&R.instanceMatrix&&(Ce=R.instanceMatrix),j==="instanceColor"&&R.instanceColor&&(Ce=R.instanceColor)),_e===void 0||_e.attribute!==Ce||Ce&&_e.data!==Ce.data)return!0;$++}return s.attributesNum!==$||s.index!==Z}function S(R,F,Q,Z){let J={},ie=F.attributes,$=0,ue=Q.getAttributes();for(let j in ue)if(ue[j].location>=0){let _e=ie[j];_e===void 0&&(j==="instanceMatrix"&&R.instanceMatrix&&(_e=R.instanceMatrix),j==="instanceColor"&&R.instanceColor&&(_e=R.instanceColor));let Ce={};Ce.attribute=_e,_e&&_e.data&&(Ce.data=_e.data),J[j]=Ce,$++}s.attributes=J,s.attributesNum=$,s.index=Z}function E(){let R=s.newAttributes;for(let F=0,Q=R.length;F<Q;F++)R[F]=0}function _(R){g(R,0)}function g(R,F){let Q=s.newAttributes,Z=s.enabledAttributes,J=s.attributeDivisors;Q[R]=1,Z[R]===0&&(i.enableVertexAttribArray(R),Z[R]=1),J[R]!==F&&(i.vertexAttribDivisor(R,F),J[R]=F)}function I(){let R=s.newAttributes,F=s.enabledAttributes;for(let Q=0,Z=F.length;Q<Z;Q++)F[Q]!==R[Q]&&(i.disableVertexAttribArray(Q),F[Q]=0)}function P(R,F,Q,Z,J,ie,$){$===!0?i.vertexAttribIPointer(R,F,Q,J,ie):i.vertexAttribPointer(R,F,Q,Z,J,ie)}function C(R,F,Q,Z){E();let J=Z.attributes,ie=Q.getAttributes(),$=F.defaultAttributeValues;for(let ue in ie){let j=ie[ue];if(j.location>=0){let ge=J[ue];if(ge===void 0&&(ue==="instanceMatrix"&&R.instanceMatrix&&(ge=R.instanceMatrix),ue==="instanceColor"&&R.instanceColor&&(ge=R.instanceColor)),ge!==void 0){let _e=ge.normalized,Ce=ge.itemSize,ke=e.get(ge);if(ke===void 0)continue;let We=ke.buffer,re=ke.type,de=ke.bytesPerElement,te=re===i.INT||re===i.UNSIGNED_INT||ge.gpuType===uc;if(ge.isInterleavedBufferAttribute){let W=ge.data,he=W.stride,Oe=ge.offset;if(W.isInstancedInterleavedBuffer){for(let Xe=0;Xe<j.locationSize;Xe++)g(j.location+Xe,W.meshPerAttribute);R.isInstancedMesh!==!0&&Z._maxInstanceCount===void 0&&(Z._maxInstanceCount=W.meshPerAttribute*W.count)}else for(let Xe=0;Xe<j.locationSize;Xe++)_(j.location+Xe);i.bindBuffer(i.ARRAY_BUFFER,We);for(let Xe=0;Xe<j.locationSize;Xe++)P(j.location+Xe,Ce/j.locationSize,re,_e,he*de,(Oe+Ce/j.locationSize*Xe)*de,te)}else{if(ge.isInstancedBufferAttribute){for(let W=0;W<j.locationSize;W++)g(j.location+W,ge.meshPerAttribute);R.isInstancedMesh!==!0&&Z._maxInstanceCount===void 0&&(Z._maxInstanceCount=ge.meshPerAttribute*ge.count)}else for(let W=0;W<j.locationSize;W++)_(j.location+W);i.bindBuffer(i.ARRAY_BUFFER,We);for(let W=0;W<j.locationSize;W++)P(j.location+W,Ce/j.locationSize,re,_e,Ce*de,Ce/j.locationSize*W*de,te)}}else if($!==void 0){let _e=$[ue];if(_e!==void 0)switch(_e.length){case 2:i.vertexAttrib2fv(j.location,_e);break;case 3:i.vertexAttrib3fv(j.location,_e);break;case 4:i.vertexAttrib4fv(j.location,_e);break;default:i.vertexAttrib1fv(j.location,_e)}}}}I()}function H(){V();for(let R in n){let F=n[R];for(let Q in F){let Z=F[Q];for(let J in Z)d(Z[J].object),delete Z[J];delete F[Q]}delete n[R]}}function U(R){if(n[R.id]===void 0)return;let F=n[R.id];for(let Q in F){let Z=F[Q];for(let J in Z)d(Z[J].object),delete Z[J];delete F[Q]}delete n[R.id]}function N(R){for(let F in n){let Q=n[F];if(Q[R.id]===void 0)continue;let Z=Q[R.id];for(let J in Z)d(Z[J].object),delete Z[J];delete Q[R.id]}}function V(){L(),a=!0,s!==r&&(s=r,h(s.object))}function L(){r.geometry=null,r.program=null,r.wireframe=!1}return{setup:o,reset:V,resetDefaultState:L,dispose:H,releaseStatesOfGeometry:U,releaseStatesOfProgram:N,initAttributes:E,enableAttribute:_,disableUnusedAttributes:I}}function Jg(i,e,t){let n;function r(h){n=h}function s(h,d){i.drawArrays(n,h,d),t.update(d,n,1)}function a(h,d,m){m!==0&&(i.drawArraysInstanced(n,h,d,m),t.update(d,n,m))}function o(h,d,m){if(m===0)return;e.get("WEBGL_multi_draw").multiDrawArraysWEBGL(n,h,0,d,0,m);let v=0;for(let S=0;S<m;S++)v+=d[S];t.update(v,n,1)}function l(h,d,m,f){if(m===0)return;let v=e.get("WEBGL_multi_draw");if(v===null)for(let S=0;S<h.length;S++)a(h[S],d[S],f[S]);else{v.multiDrawArraysInstancedWEBGL(n,h,0,d,0,f,0,m);let S=0;for(let E=0;E<m;E++)S+=d[E]*f[E];t.update(S,n,1)}}this.setMode=r,this.render=s,this.renderInstances=a,this.renderMultiDraw=o,this.renderMultiDrawInstances=l}function Qg(i,e,t,n){let r;function s(){if(r!==void 0)return r;if(e.has("EXT_texture_filter_anisotropic")===!0){let N=e.get("EXT_texture_filter_anisotropic");r=i.getParameter(N.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else r=0;return r}function a(N){return!(N!==sn&&n.convert(N)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_FORMAT))}function o(N){let V=N===Ir&&(e.has("EXT_color_buffer_half_float")||e.has("EXT_color_buffer_float"));return!(N!==Rn&&n.convert(N)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_TYPE)&&N!==Tn&&!V)}function l(N){if(N==="highp"){if(i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.HIGH_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.HIGH_FLOAT).precision>0)return"highp";N="mediump"}return N==="mediump"&&i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.MEDIUM_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let h=t.precision!==void 0?t.precision:"highp",d=l(h);d!==h&&(console.warn("THREE.WebGLRenderer:",h,"not supported, using",d,"instead."),h=d);let m=t.logarithmicDepthBuffer===!0,f=t.reverseDepthBuffer===!0&&e.has("EXT_clip_control"),v=i.getParameter(i.MAX_TEXTURE_IMAGE_UNITS),S=i.getParameter(i.MAX_VERTEX_TEXTURE_IMAGE_UNITS),E=i.getParameter(i.MAX_TEXTURE_SIZE),_=i.getParameter(i.MAX_CUBE_MAP_TEXTURE_SIZE),g=i.getParameter(i.MAX_VERTEX_ATTRIBS),I=i.getParameter(i.MAX_VERTEX_UNIFORM_VECTORS),P=i.getParameter(i.MAX_VARYING_VECTORS),C=i.getParameter(i.MAX_FRAGMENT_UNIFORM_VECTORS),H=S>0,U=i.getParameter(i.MAX_SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:s,getMaxPrecision:l,textureFormatReadable:a,textureTypeReadable:o,precision:h,logarithmicDepthBuffer:m,reverseDepthBuffer:f,maxTextures:v,maxVertexTextures:S,maxTextureSize:E,maxCubemapSize:_,maxAttributes:g,maxVertexUniforms:I,maxVaryings:P,maxFragmentUniforms:C,vertexTextures:H,maxSamples:U}}function ev(i){let e=this,t=null,n=0,r=!1,s=!1,a=new rn,o=new He,l={value:null,needsUpdate:!1};this.uniform=l,this.numPlanes=0,this.numIntersection=0,this.init=function(m,f){let v=m.length!==0||f||n!==0||r;return r=f,n=m.length,v},this.beginShadows=function(){s=!0,d(null)},this.endShadows=function(){s=!1},this.setGlobalState=function(m,f){t=d(m,f,0)},this.setState=function(m,f,v){let S=m.clippingPlanes,E=m.clipIntersection,_=m.clipShadows,g=i.get(m);if(!r||S===null||S.length===0||s&&!_)s?d(null):h();else{let I=s?0:n,P=I*4,C=g.clippingState||null;l.value=C,C=d(S,f,P,v);for(let H=0;H!==P;++H)C[H]=t[H];g.clippingState=C,this.numIntersection=E?this.numPlanes:0,this.numPlanes+=I}};function h(){l.value!==t&&(l.value=t,l.needsUpdate=n>0),e.numPlanes=n,e.numIntersection=0}function d(m,f,v,S){let E=m!==null?m.length:0,_=null;if(E!==0){if(_=l.value,S!==!0||_===null){let g=v+E*4,I=f.matrixWorldInverse;o.getNormalMatrix(I),(_===null||_.length<g)&&(_=new Float32Array(g));for(let P=0,C=v;P!==E;++P,C+=4)a.copy(m[P]).applyMatrix4(I,o),a.normal.toArray(_,C),_[C+3]=a.constant}l.value=_,l.needsUpdate=!0}return e.numPlanes=E,e.numIntersection=0,_}}function tv(i){let e=new WeakMap;function t(a,o){return o===ro?a.mapping=$i:o===so&&(a.mapping=Ki),a}function n(a){if(a&&a.isTexture){let o=a.mapping;if(o===ro||o===so)if(e.has(a)){let l=e.get(a).texture;return t(l,a.mapping)}else{let l=a.image;if(l&&l.height>0){let h=new zo(l.height);return h.fromEquirectangularTexture(i,a),e.set(a,h),a.addEventListener("dispose",r),t(h.texture,a.mapping)}else return null}}return a}function r(a){let o=a.target;o.removeEventListener("dispose",r);let l=e.get(o);l!==void 0&&(e.delete(o),l.dispose())}function s(){e=new WeakMap}return{get:n,dispose:s}}var Go=class extends Is{constructor(e=-1,t=1,n=1,r=-1,s=.1,a=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=e,this.right=t,this.top=n,this.bottom=r,this.near=s,this.far=a,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.left=e.left,this.right=e.right,this.top=e.top,this.bottom=e.bottom,this.near=e.near,this.far=e.far,this.zoom=e.zoom,this.view=e.view===null?null:Object.assign({},e.view),this}setViewOffset(e,t,n,r,s,a){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=n,this.view.offsetY=r,this.view.width=s,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=(this.right-this.left)/(2*this.zoom),t=(this.top-this.bottom)/(2*this.zoom),n=(this.right+this.left)/2,r=(this.top+this.bottom)/2,s=n-e,a=n+e,o=r+t,l=r-t;if(this.view!==null&&this.view.enabled){let h=(this.right-this.left)/this.view.fullWidth/this.zoom,d=(this.top-this.bottom)/this.view.fullHeight/this.zoom;s+=h*this.view.offsetX,a=s+h*this.view.width,o-=d*this.view.offsetY,l=o-d*this.view.height}this.projectionMatrix.makeOrthographic(s,a,o,l,this.near,this.far,this.coordinateSystem),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.zoom=this.zoom,t.object.left=this.left,t.object.right=this.right,t.object.top=this.top,t.object.bottom=this.bottom,t.object.near=this.near,t.object.far=this.far,this.view!==null&&(t.object.view=Object.assign({},this.view)),t}},Vi=4,dh=[.125,.215,.35,.446,.526,.582],di=20,Ha=new Go,fh=new tt,Wa=null,Xa=0,qa=0,Ya=!1,li=(1+Math.sqrt(5))/2,zi=1/li,ph=[new X(-li,zi,0),new X(li,zi,0),new X(-zi,0,li),new X(zi,0,li),new X(0,li,-zi),new X(0,li,zi),new X(-1,1,-1),new X(1,1,-1),new X(-1,1,1),new X(1,1,1)],Fs=class{constructor(e){this._renderer=e,this._pingPongRenderTarget=null,this._lodMax=0,this._cubeSize=0,this._lodPlanes=[],this._sizeLods=[],this._sigmas=[],this._blurMaterial=null,this._cubemapMaterial=null,this._equirectMaterial=null,this._compileMaterial(this._blurMaterial)}fromScene(e,t=0,n=.1,r=100){Wa=this._renderer.getRenderTarget(),Xa=this._renderer.getActiveCubeFace(),qa=this._renderer.getActiveMipmapLevel(),Ya=this._renderer.xr.enabled,this._renderer.xr.enabled=!1,this._setSize(256);let s=this._allocateTargets();return s.depthBuffer=!0,this._sceneToCubeUV(e,n,r,s),t>0&&this._blur(s,0,0,t),this._applyPMREM(s),this._cleanup(s),s}fromEquirectangular(e,t=null){return this._fromTexture(e,t)}fromCubemap(e,t=null){return this._fromTexture(e,t)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=vh(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=gh(),this._compileMaterial(this._equirectMaterial))}dispose(){this._dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose()}_setSize(e){this._lodMax=Math.floor(Math.log2(e)),this._cubeSize=Math.pow(2,this._lodMax)}_dispose(){this._blurMaterial!==null&&this._blurMaterial.dispose(),this._pingPongRenderTarget!==null&&this._pingPongRenderTarget.dispose();for(let e=0;e<this._lodPlanes.length;e++)this._lodPlanes[e].dispose()}_cleanup(e){this._renderer.setRenderTarget(Wa,Xa,qa),this._renderer.xr.enabled=Ya,e.scissorTest=!1,fs(e,0,0,e.width,e.height)}_fromTexture(e,t){e.mapping===$i||e.mapping===Ki?this._setSize(e.image.length===0?16:e.image[0].width||e.image[0].image.width):this._setSize(e.image.width/4),Wa=this._renderer.getRenderTarget(),Xa=this._renderer.getActiveCubeFace(),qa=this._renderer.getActiveMipmapLevel(),Ya=this._renderer.xr.enabled,this._renderer.xr.enabled=!1;let n=t||this._allocateTargets();return this._textureToCubeUV(e,n),this._applyPMREM(n),this._cleanup(n),n}_allocateTargets(){let e=3*Math.max(this._cubeSize,112),t=4*this._cubeSize,n={magFilter:fn,minFilter:fn,generateMipmaps:!1,type:Ir,format:sn,colorSpace:ir,depthBuffer:!1},r=mh(e,t,n);if(this._pingPongRenderTarget===null||this._pingPongRenderTarget.width!==e||this._pingPongRenderTarget.height!==t){this._pingPongRenderTarget!==null&&this._dispose(),this._pingPongRenderTarget=mh(e,t,n);let{_lodMax:s}=this;({sizeLods:this._sizeLods,lodPlanes:this._lodPlanes,sigmas:this._sigmas}=nv(s)),this._blurMaterial=iv(s,e,t)}return r}_compileMaterial(e){let t=new an(this._lodPlanes[0],e);this._renderer.compile(t,Ha)}_sceneToCubeUV(e,t,n,r){let o=new Nt(90,1,t,n),l=[1,-1,1,1,1,1],h=[1,1,1,-1,-1,-1],d=this._renderer,m=d.autoClear,f=d.toneMapping;d.getClearColor(fh),d.toneMapping=$n,d.autoClear=!1;let v=new Rs({name:"PMREM.Background",side:kt,depthWrite:!1,depthTest:!1}),S=new an(new Rr,v),E=!1,_=e.background;_?_.isColor&&(v.color.copy(_),e.background=null,E=!0):(v.color.copy(fh),E=!0);for(let g=0;g<6;g++){let I=g%3;I===0?(o.up.set(0,l[g],0),o.lookAt(h[g],0,0)):I===1?(o.up.set(0,0,l[g]),o.lookAt(0,h[g],0)):(o.up.set(0,l[g],0),o.lookAt(0,0,h[g]));let P=this._cubeSize;fs(r,I*P,g>2?P:0,P,P),d.setRenderTarget(r),E&&d.render(S,o),d.render(e,o)}S.geometry.dispose(),S.material.dispose(),d.toneMapping=f,d.autoClear=m,e.background=_}_textureToCubeUV(e,t){let n=this._renderer,r=e.mapping===$i||e.mapping===Ki;r?(this._cubemapMaterial===null&&(this._cubemapMaterial=vh()),this._cubemapMaterial.uniforms.flipEnvMap.value=e.isRenderTargetTexture===!1?-1:1):this._equirectMaterial===null&&(this._equirectMaterial=gh());let s=r?this._cubemapMaterial:this._equirectMaterial,a=new an(this._lodPlanes[0],s),o=s.uniforms;o.envMap.value=e;let l=this._cubeSize;fs(t,0,0,3*l,2*l),n.setRenderTarget(t),n.render(a,Ha)}_applyPMREM(e){let t=this._renderer,n=t.autoClear;t.autoClear=!1;let r=this._lodPlanes.length;for(let s=1;s<r;s++){let a=Math.sqrt(this._sigmas[s]*this._sigmas[s]-this._sigmas[s-1]*this._sigmas[s-1]),o=ph[(r-s-1)%ph.length];this._blur(e,s-1,s,a,o)}t.autoClear=n}_blur(e,t,n,r,s){let a=this._pingPongRenderTarget;this._halfBlur(e,a,t,n,r,"latitudinal",s),this._halfBlur(a,e,n,n,r,"longitudinal",s)}_halfBlur(e,t,n,r,s,a,o){let l=this._renderer,h=this._blurMaterial;a!=="latitudinal"&&a!=="longitudinal"&&console.error("blur direction must be either latitudinal or longitudinal!");let d=3,m=new an(this._lodPlanes[r],h),f=h.uniforms,v=this._sizeLods[n]-1,S=isFinite(s)?Math.PI/(2*v):2*Math.PI/(2*di-1),E=s/S,_=isFinite(s)?1+Math.floor(d*E):di;_>di&&console.warn(`sigmaRadians, ${s}, is too large and will clip, as it requested ${_} samples when the maximum is set to ${di}`);let g=[],I=0;for(let N=0;N<di;++N){let V=N/E,L=Math.exp(-V*V/2);g.push(L),N===0?I+=L:N<_&&(I+=2*L)}for(let N=0;N<g.length;N++)g[N]=g[N]/I;f.envMap.value=e.texture,f.samples.value=_,f.weights.value=g,f.latitudinal.value=a==="latitudinal",o&&(f.poleAxis.value=o);let{_lodMax:P}=this;f.dTheta.value=S,f.mipInt.value=P-n;let C=this._sizeLods[r],H=3*C*(r>P-Vi?r-P+Vi:0),U=4*(this._cubeSize-C);fs(t,H,U,3*C,2*C),l.setRenderTarget(t),l.render(m,Ha)}};function nv(i){let e=[],t=[],n=[],r=i,s=i-Vi+1+dh.length;for(let a=0;a<s;a++){let o=Math.pow(2,r);t.push(o);let l=1/o;a>i-Vi?l=dh[a-i+Vi-1]:a===0&&(l=0),n.push(l);let h=1/(o-2),d=-h,m=1+h,f=[d,d,m,d,m,m,d,d,m,m,d,m],v=6,S=6,E=3,_=2,g=1,I=new Float32Array(E*S*v),P=new Float32Array(_*S*v),C=new Float32Array(g*S*v);for(let U=0;U<v;U++){let N=U%3*2/3-1,V=U>2?0:-1,L=[N,V,0,N+2/3,V,0,N+2/3,V+1,0,N,V,0,N+2/3,V+1,0,N,V+1,0];I.set(L,E*S*U),P.set(f,_*S*U);let R=[U,U,U,U,U,U];C.set(R,g*S*U)}let H=new pn;H.setAttribute("position",new Zt(I,E)),H.setAttribute("uv",new Zt(P,_)),H.setAttribute("faceIndex",new Zt(C,g)),e.push(H),r>Vi&&r--}return{lodPlanes:e,sizeLods:t,sigmas:n}}function mh(i,e,t){let n=new Ln(i,e,t);return n.texture.mapping=Hs,n.texture.name="PMREM.cubeUv",n.scissorTest=!0,n}function fs(i,e,t,n,r){i.viewport.set(e,t,n,r),i.scissor.set(e,t,n,r)}function iv(i,e,t){let n=new Float32Array(di),r=new X(0,1,0);return new mn({name:"SphericalGaussianBlur",defines:{n:di,CUBEUV_TEXEL_WIDTH:1/e,CUBEUV_TEXEL_HEIGHT:1/t,CUBEUV_MAX_MIP:`${i}.0`},uniforms:{envMap:{value:null},samples:{value:1},weights:{value:n},latitudinal:{value:!1},dTheta:{value:0},mipInt:{value:0},poleAxis:{value:r}},vertexShader:_c(),fragmentShader:`

			precision mediump float;
			precision mediump int;

			varying vec3 vOutputDirection;

			uniform sampler2D envMap;
			uniform int samples;
			uniform float weights[ n ];
			uniform bool latitudinal;
			uniform float dTheta;
			uniform float mipInt;
			uniform vec3 poleAxis;

			#define ENVMAP_TYPE_CUBE_UV
			#include <cube_uv_reflection_fragment>

			vec3 getSample( float theta, vec3 axis ) {

				float cosTheta = cos( theta );
				// Rodrigues' axis-angle rotation
				vec3 sampleDirection = vOutputDirection * cosTheta
					+ cross( axis, vOutputDirection ) * sin( theta )
					+ axis * dot( axis, vOutputDirection ) * ( 1.0 - cosTheta );

				return bilinearCubeUV( envMap, sampleDirection, mipInt );

			}

			void main() {

				vec3 axis = latitudinal ? poleAxis : cross( poleAxis, vOutputDirection );

				if ( all( equal( axis, vec3( 0.0 ) ) ) ) {

					axis = vec3( vOutputDirection.z, 0.0, - vOutputDirection.x );

				}

				axis = normalize( axis );

				gl_FragColor = vec4( 0.0, 0.0, 0.0, 1.0 );
				gl_FragColor.rgb += weights[ 0 ] * getSample( 0.0, axis );

				for ( int i = 1; i < n; i++ ) {

					if ( i >= samples ) {

						break;

					}

					float theta = dTheta * float( i );
					gl_FragColor.rgb += weights[ i ] * getSample( -1.0 * theta, axis );
					gl_FragColor.rgb += weights[ i ] * getSample( theta, axis );

				}

			}
		`,blending:Zn,depthTest:!1,depthWrite:!1})}function gh(){return new mn({name:"EquirectangularToCubeUV",uniforms:{envMap:{value:null}},vertexShader:_c(),fragmentShader:`

			precision mediump float;
			precision mediump int;

			varying vec3 vOutputDirection;

			uniform sampler2D envMap;

			#include <common>

			void main() {

				vec3 outputDirection = normalize( vOutputDirection );
				vec2 uv = equirectUv( outputDirection );

				gl_FragColor = vec4( texture2D ( envMap, uv ).rgb, 1.0 );

			}
		`,blending:Zn,depthTest:!1,depthWrite:!1})}function vh(){return new mn({name:"CubemapToCubeUV",uniforms:{envMap:{value:null},flipEnvMap:{value:-1}},vertexShader:_c(),fragmentShader:`

			precision mediump float;
			precision mediump int;

			uniform float flipEnvMap;

			varying vec3 vOutputDirection;

			uniform samplerCube envMap;

			void main() {

				gl_FragColor = textureCube( envMap, vec3( flipEnvMap * vOutputDirection.x, vOutputDirection.yz ) );

			}
		`,blending:Zn,depthTest:!1,depthWrite:!1})}function _c(){return`

		precision mediump float;
		precision mediump int;

		attribute float faceIndex;

		varying vec3 vOutputDirection;

		// RH coordinate system; PMREM face-indexing convention
		vec3 getDirection( vec2 uv, float face ) {

			uv = 2.0 * uv - 1.0;

			vec3 direction = vec3( uv, 1.0 );

			if ( face == 0.0 ) {

				direction = direction.zyx; // ( 1, v, u ) pos x

			} else if ( face == 1.0 ) {

				direction = direction.xzy;
				direction.xz *= -1.0; // ( -u, 1, -v ) pos y

			} else if ( face == 2.0 ) {

				direction.x *= -1.0; // ( -u, v, 1 ) pos z

			} else if ( face == 3.0 ) {

				direction = direction.zyx;
				direction.xz *= -1.0; // ( -1, v, -u ) neg x

			} else if ( face == 4.0 ) {

				direction = direction.xzy;
				direction.xy *= -1.0; // ( -u, -1, v ) neg y

			} else if ( face == 5.0 ) {

				direction.z *= -1.0; // ( u, v, -1 ) neg z

			}

			return direction;

		}

		void main() {

			vOutputDirection = getDirection( uv, faceIndex );
			gl_Position = vec4( position, 1.0 );

		}
	`}function rv(i){let e=new WeakMap,t=null;function n(o){if(o&&o.isTexture){let l=o.mapping,h=l===ro||l===so,d=l===$i||l===Ki;if(h||d){let m=e.get(o),f=m!==void 0?m.texture.pmremVersion:0;if(o.isRenderTargetTexture&&o.pmremVersion!==f)return t===null&&(t=new Fs(i)),m=h?t.fromEquirectangular(o,m):t.fromCubemap(o,m),m.texture.pmremVersion=o.pmremVersion,e.set(o,m),m.texture;if(m!==void 0)return m.texture;{let v=o.image;return h&&v&&v.height>0||d&&v&&r(v)?(t===null&&(t=new Fs(i)),m=h?t.fromEquirectangular(o):t.fromCubemap(o),m.texture.pmremVersion=o.pmremVersion,e.set(o,m),o.addEventListener("dispose",s),m.texture):null}}}return o}function r(o){let l=0,h=6;for(let d=0;d<h;d++)o[d]!==void 0&&l++;return l===h}function s(o){let l=o.target;l.removeEventListener("dispose",s);let h=e.get(l);h!==void 0&&(e.delete(l),h.dispose())}function a(){e=new WeakMap,t!==null&&(t.dispose(),t=null)}return{get:n,dispose:a}}function sv(i){let e={};function t(n){if(e[n]!==void 0)return e[n];let r;switch(n){case"WEBGL_depth_texture":r=i.getExtension("WEBGL_depth_texture")||i.getExtension("MOZ_WEBGL_depth_texture")||i.getExtension("WEBKIT_WEBGL_depth_texture");break;case"EXT_texture_filter_anisotropic":r=i.getExtension("EXT_texture_filter_anisotropic")||i.getExtension("MOZ_EXT_texture_filter_anisotropic")||i.getExtension("WEBKIT_EXT_texture_filter_anisotropic");break;case"WEBGL_compressed_texture_s3tc":r=i.getExtension("WEBGL_compressed_texture_s3tc")||i.getExtension("MOZ_WEBGL_compressed_texture_s3tc")||i.getExtension("WEBKIT_WEBGL_compressed_texture_s3tc");break;case"WEBGL_compressed_texture_pvrtc":r=i.getExtension("WEBGL_compressed_texture_pvrtc")||i.getExtension("WEBKIT_WEBGL_compressed_texture_pvrtc");break;default:r=i.getExtension(n)}return e[n]=r,r}return{has:function(n){return t(n)!==null},init:function(){t("EXT_color_buffer_float"),t("WEBGL_clip_cull_distance"),t("OES_texture_float_linear"),t("EXT_color_buffer_half_float"),t("WEBGL_multisampled_render_to_texture"),t("WEBGL_render_shared_exponent")},get:function(n){let r=t(n);return r===null&&Sr("THREE.WebGLRenderer: "+n+" extension not supported."),r}}}function av(i,e,t,n){let r={},s=new WeakMap;function a(m){let f=m.target;f.index!==null&&e.remove(f.index);for(let S in f.attributes)e.remove(f.attributes[S]);for(let S in f.morphAttributes){let E=f.morphAttributes[S];for(let _=0,g=E.length;_<g;_++)e.remove(E[_])}f.removeEventListener("dispose",a),delete r[f.id];let v=s.get(f);v&&(e.remove(v),s.delete(f)),n.releaseStatesOfGeometry(f),f.isInstancedBufferGeometry===!0&&delete f._maxInstanceCount,t.memory.geometries--}function o(m,f){return r[f.id]===!0||(f.addEventListener("dispose",a),r[f.id]=!0,t.memory.geometries++),f}function l(m){let f=m.attributes;for(let S in f)e.update(f[S],i.ARRAY_BUFFER);let v=m.morphAttributes;for(let S in v){let E=v[S];for(let _=0,g=E.length;_<g;_++)e.update(E[_],i.ARRAY_BUFFER)}}function h(m){let f=[],v=m.index,S=m.attributes.position,E=0;if(v!==null){let I=v.array;E=v.version;for(let P=0,C=I.length;P<C;P+=3){let H=I[P+0],U=I[P+1],N=I[P+2];f.push(H,U,U,N,N,H)}}else if(S!==void 0){let I=S.array;E=S.version;for(let P=0,C=I.length/3-1;P<C;P+=3){let H=P+0,U=P+1,N=P+2;f.push(H,U,U,N,N,H)}}else return;let _=new(Qh(f)?Ls:Ps)(f,1);_.version=E;let g=s.get(m);g&&e.remove(g),s.set(m,_)}function d(m){let f=s.get(m);if(f){let v=m.index;v!==null&&f.version<v.version&&h(m)}else h(m);return s.get(m)}return{get:o,update:l,getWireframeAttribute:d}}function ov(i,e,t){let n;function r(f){n=f}let s,a;function o(f){s=f.type,a=f.bytesPerElement}function l(f,v){i.drawElements(n,v,s,f*a),t.update(v,n,1)}function h(f,v,S){S!==0&&(i.drawElementsInstanced(n,v,s,f*a,S),t.update(v,n,S))}function d(f,v,S){if(S===0)return;e.get("WEBGL_multi_draw").multiDrawElementsWEBGL(n,v,0,s,f,0,S);let _=0;for(let g=0;g<S;g++)_+=v[g];t.update(_,n,1)}function m(f,v,S,E){if(S===0)return;let _=e.get("WEBGL_multi_draw");if(_===null)for(let g=0;g<f.length;g++)h(f[g]/a,v[g],E[g]);else{_.multiDrawElementsInstancedWEBGL(n,v,0,s,f,0,E,0,S);let g=0;for(let I=0;I<S;I++)g+=v[I]*E[I];t.update(g,n,1)}}this.setMode=r,this.setIndex=o,this.render=l,this.renderInstances=h,this.renderMultiDraw=d,this.renderMultiDrawInstances=m}function cv(i){let e={geometries:0,textures:0},t={frame:0,calls:0,triangles:0,points:0,lines:0};function n(s,a,o){switch(t.calls++,a){case i.TRIANGLES:t.triangles+=o*(s/3);break;case i.LINES:t.lines+=o*(s/2);break;case i.LINE_STRIP:t.lines+=o*(s-1);break;case i.LINE_LOOP:t.lines+=o*s;break;case i.POINTS:t.points+=o*s;break;default:console.error("THREE.WebGLInfo: Unknown draw mode:",a);break}}function r(){t.calls=0,t.triangles=0,t.points=0,t.lines=0}return{memory:e,render:t,programs:null,autoReset:!0,reset:r,update:n}}function lv(i,e,t){let n=new WeakMap,r=new gt;function s(a,o,l){let h=a.morphTargetInfluences,d=o.morphAttributes.position||o.morphAttributes.normal||o.morphAttributes.color,m=d!==void 0?d.length:0,f=n.get(o);if(f===void 0||f.count!==m){let L=function(){N.dispose(),n.delete(o),o.removeEventListener("dispose",L)};f!==void 0&&f.texture.dispose();let v=o.morphAttributes.position!==void 0,S=o.morphAttributes.normal!==void 0,E=o.morphAttributes.color!==void 0,_=o.morphAttributes.position||[],g=o.morphAttributes.normal||[],I=o.morphAttributes.color||[],P=0;v===!0&&(P=1),S===!0&&(P=2),E===!0&&(P=3);let C=o.attributes.position.count*P,H=1;C>e.maxTextureSize&&(H=Math.ceil(C/e.maxTextureSize),C=e.maxTextureSize);let U=new Float32Array(C*H*4*m),N=new As(U,C,H,m);N.type=Tn,N.needsUpdate=!0;let V=P*4;for(let R=0;R<m;R++){let F=_[R],Q=g[R],Z=I[R],J=C*H*4*R;for(let ie=0;ie<F.count;ie++){let $=ie*V;v===!0&&(r.fromBufferAttribute(F,ie),U[J+$+0]=r.x,U[J+$+1]=r.y,U[J+$+2]=r.z,U[J+$+3]=0),S===!0&&(r.fromBufferAttribute(Q,ie),U[J+$+4]=r.x,U[J+$+5]=r.y,U[J+$+6]=r.z,U[J+$+7]=0),E===!0&&(r.fromBufferAttribute(Z,ie),U[J+$+8]=r.x,U[J+$+9]=r.y,U[J+$+10]=r.z,U[J+$+11]=Z.itemSize===4?r.w:1)}}f={count:m,texture:N,size:new $e(C,H)},n.set(o,f),o.addEventListener("dispose",L)}if(a.isInstancedMesh===!0&&a.morphTexture!==null)l.getUniforms().setValue(i,"morphTexture",a.morphTexture,t);else{let v=0;for(let E=0;E<h.length;E++)v+=h[E];let S=o.morphTargetsRelative?1:1-v;l.getUniforms().setValue(i,"morphTargetBaseInfluence",S),l.getUniforms().setValue(i,"morphTargetInfluences",h)}l.getUniforms().setValue(i,"morphTargetsTexture",f.texture,t),l.getUniforms().setValue(i,"morphTargetsTextureSize",f.size)}return{update:s}}function hv(i,e,t,n){let r=new WeakMap;function s(l){let h=n.render.frame,d=l.geometry,m=e.get(l,d);if(r.get(m)!==h&&(e.update(m),r.set(m,h)),l.isInstancedMesh&&(l.hasEventListener("dispose",o)===!1&&l.addEventListener("dispose",o),r.get(l)!==h&&(t.update(l.instanceMatrix,i.ARRAY_BUFFER),l.instanceColor!==null&&t.update(l.instanceColor,i.ARRAY_BUFFER),r.set(l,h))),l.isSkinnedMesh){let f=l.skeleton;r.get(f)!==h&&(f.update(),r.set(f,h))}return m}function a(){r=new WeakMap}function o(l){let h=l.target;h.removeEventListener("dispose",o),t.remove(h.instanceMatrix),h.instanceColor!==null&&t.remove(h.instanceColor)}return{update:s,dispose:a}}var Os=class extends $t{constructor(e,t,n,r,s,a,o,l,h,d=Xi){if(d!==Xi&&d!==Ji)throw new Error("DepthTexture format must be either THREE.DepthFormat or THREE.DepthStencilFormat");n===void 0&&d===Xi&&(n=mi),n===void 0&&d===Ji&&(n=ji),super(null,r,s,a,o,l,d,n,h),this.isDepthTexture=!0,this.image={width:e,height:t},this.magFilter=o!==void 0?o:on,this.minFilter=l!==void 0?l:on,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(e){return super.copy(e),this.compareFunction=e.compareFunction,this}toJSON(e){let t=super.toJSON(e);return this.compareFunction!==null&&(t.compareFunction=this.compareFunction),t}},iu=new $t,_h=new Os(1,1),ru=new As,su=new ko,au=new Ds,yh=[],xh=[],bh=new Float32Array(16),Sh=new Float32Array(9),Mh=new Float32Array(4);function sr(i,e,t){let n=i[0];if(n<=0||n>0)return i;let r=e*t,s=yh[r];if(s===void 0&&(s=new Float32Array(r),yh[r]=s),e!==0){n.toArray(s,0);for(let a=1,o=0;a!==e;++a)o+=t,i[a].toArray(s,o)}return s}function bt(i,e){if(i.length!==e.length)return!1;for(let t=0,n=i.length;t<n;t++)if(i[t]!==e[t])return!1;return!0}function St(i,e){for(let t=0,n=e.length;t<n;t++)i[t]=e[t]}function Xs(i,e){let t=xh[e];t===void 0&&(t=new Int32Array(e),xh[e]=t);for(let n=0;n!==e;++n)t[n]=i.allocateTextureUnit();return t}function uv(i,e){let t=this.cache;t[0]!==e&&(i.uniform1f(this.addr,e),t[0]=e)}function dv(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2f(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(bt(t,e))return;i.uniform2fv(this.addr,e),St(t,e)}}function fv(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3f(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else if(e.r!==void 0)(t[0]!==e.r||t[1]!==e.g||t[2]!==e.b)&&(i.uniform3f(this.addr,e.r,e.g,e.b),t[0]=e.r,t[1]=e.g,t[2]=e.b);else{if(bt(t,e))return;i.uniform3fv(this.addr,e),St(t,e)}}function pv(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4f(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(bt(t,e))return;i.uniform4fv(this.addr,e),St(t,e)}}function mv(i,e){let t=this.cache,n=e.elements;if(n===void 0){if(bt(t,e))return;i.uniformMatrix2fv(this.addr,!1,e),St(t,e)}else{if(bt(t,n))return;Mh.set(n),i.uniformMatrix2fv(this.addr,!1,Mh),St(t,n)}}function gv(i,e){let t=this.cache,n=e.elements;if(n===void 0){if(bt(t,e))return;i.uniformMatrix3fv(this.addr,!1,e),St(t,e)}else{if(bt(t,n))return;Sh.set(n),i.uniformMatrix3fv(this.addr,!1,Sh),St(t,n)}}function vv(i,e){let t=this.cache,n=e.elements;if(n===void 0){if(bt(t,e))return;i.uniformMatrix4fv(this.addr,!1,e),St(t,e)}else{if(bt(t,n))return;bh.set(n),i.uniformMatrix4fv(this.addr,!1,bh),St(t,n)}}function _v(i,e){let t=this.cache;t[0]!==e&&(i.uniform1i(this.addr,e),t[0]=e)}function yv(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2i(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(bt(t,e))return;i.uniform2iv(this.addr,e),St(t,e)}}function xv(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3i(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(bt(t,e))return;i.uniform3iv(this.addr,e),St(t,e)}}function bv(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4i(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(bt(t,e))return;i.uniform4iv(this.addr,e),St(t,e)}}function Sv(i,e){let t=this.cache;t[0]!==e&&(i.uniform1ui(this.addr,e),t[0]=e)}function Mv(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2ui(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(bt(t,e))return;i.uniform2uiv(this.addr,e),St(t,e)}}function wv(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3ui(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(bt(t,e))return;i.uniform3uiv(this.addr,e),St(t,e)}}function Ev(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4ui(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(bt(t,e))return;i.uniform4uiv(this.addr,e),St(t,e)}}function Tv(i,e,t){let n=this.cache,r=t.allocateTextureUnit();n[0]!==r&&(i.uniform1i(this.addr,r),n[0]=r);let s;this.type===i.SAMPLER_2D_SHADOW?(_h.compareFunction=jh,s=_h):s=iu,t.setTexture2D(e||s,r)}function Av(i,e,t){let n=this.cache,r=t.allocateTextureUnit();n[0]!==r&&(i.uniform1i(this.addr,r),n[0]=r),t.setTexture3D(e||su,r)}function Cv(i,e,t){let n=this.cache,r=t.allocateTextureUnit();n[0]!==r&&(i.uniform1i(this.addr,r),n[0]=r),t.setTextureCube(e||au,r)}function Rv(i,e,t){let n=this.cache,r=t.allocateTextureUnit();n[0]!==r&&(i.uniform1i(this.addr,r),n[0]=r),t.setTexture2DArray(e||ru,r)}function Pv(i){switch(i){case 5126:return uv;case 35664:return dv;case 35665:return fv;case 35666:return pv;case 35674:return mv;case 35675:return gv;case 35676:return vv;case 5124:case 35670:return _v;case 35667:case 35671:return yv;case 35668:case 35672:return xv;case 35669:case 35673:return bv;case 5125:return Sv;case 36294:return Mv;case 36295:return wv;case 36296:return Ev;case 35678:case 36198:case 36298:case 36306:case 35682:return Tv;case 35679:case 36299:case 36307:return Av;case 35680:case 36300:case 36308:case 36293:return Cv;case 36289:case 36303:case 36311:case 36292:return Rv}}function Lv(i,e){i.uniform1fv(this.addr,e)}function Iv(i,e){let t=sr(e,this.size,2);i.uniform2fv(this.addr,t)}function Dv(i,e){let t=sr(e,this.size,3);i.uniform3fv(this.addr,t)}function Nv(i,e){let t=sr(e,this.size,4);i.uniform4fv(this.addr,t)}function Uv(i,e){let t=sr(e,this.size,4);i.uniformMatrix2fv(this.addr,!1,t)}function Fv(i,e){let t=sr(e,this.size,9);i.uniformMatrix3fv(this.addr,!1,t)}function Ov(i,e){let t=sr(e,this.size,16);i.uniformMatrix4fv(this.addr,!1,t)}function kv(i,e){i.uniform1iv(this.addr,e)}function Bv(i,e){i.uniform2iv(this.addr,e)}function zv(i,e){i.uniform3iv(this.addr,e)}function Gv(i,e){i.uniform4iv(this.addr,e)}function Vv(i,e){i.uniform1uiv(this.addr,e)}function Hv(i,e){i.uniform2uiv(this.addr,e)}function Wv(i,e){i.uniform3uiv(this.addr,e)}function Xv(i,e){i.uniform4uiv(this.addr,e)}function qv(i,e,t){let n=this.cache,r=e.length,s=Xs(t,r);bt(n,s)||(i.uniform1iv(this.addr,s),St(n,s));for(let a=0;a!==r;++a)t.setTexture2D(e[a]||iu,s[a])}function Yv(i,e,t){let n=this.cache,r=e.length,s=Xs(t,r);bt(n,s)||(i.uniform1iv(this.addr,s),St(n,s));for(let a=0;a!==r;++a)t.setTexture3D(e[a]||su,s[a])}function Zv(i,e,t){let n=this.cache,r=e.length,s=Xs(t,r);bt(n,s)||(i.uniform1iv(this.addr,s),St(n,s));for(let a=0;a!==r;++a)t.setTextureCube(e[a]||au,s[a])}function $v(i,e,t){let n=this.cache,r=e.length,s=Xs(t,r);bt(n,s)||(i.uniform1iv(this.addr,s),St(n,s));for(let a=0;a!==r;++a)t.setTexture2DArray(e[a]||ru,s[a])}function Kv(i){switch(i){case 5126:return Lv;case 35664:return Iv;case 35665:return Dv;case 35666:return Nv;case 35674:return Uv;case 35675:return Fv;case 35676:return Ov;case 5124:case 35670:return kv;case 35667:case 35671:return Bv;case 35668:case 35672:return zv;case 35669:case 35673:return Gv;case 5125:return Vv;case 36294:return Hv;case 36295:return Wv;case 36296:return Xv;case 35678:case 36198:case 36298:case 36306:case 35682:return qv;case 35679:case 36299:case 36307:return Yv;case 35680:case 36300:case 36308:case 36293:return Zv;case 36289:case 36303:case 36311:case 36292:return $v}}var Vo=class{constructor(e,t,n){this.id=e,this.addr=n,this.cache=[],this.type=t.type,this.setValue=Pv(t.type)}},Ho=class{constructor(e,t,n){this.id=e,this.addr=n,this.cache=[],this.type=t.type,this.size=t.size,this.setValue=Kv(t.type)}},Wo=class{constructor(e){this.id=e,this.seq=[],this.map={}}setValue(e,t,n){let r=this.seq;for(let s=0,a=r.length;s!==a;++s){let o=r[s];o.setValue(e,t[o.id],n)}}},Za=/(\w+)(\])?(\[|\.)?/g;function wh(i,e){i.seq.push(e),i.map[e.id]=e}function jv(i,e,t){let n=i.name,r=n.length;for(Za.lastIndex=0;;){let s=Za.exec(n),a=Za.lastIndex,o=s[1],l=s[2]==="]",h=s[3];if(l&&(o=o|0),h===void 0||h==="["&&a+2===r){wh(t,h===void 0?new Vo(o,i,e):new Ho(o,i,e));break}else{let m=t.map[o];m===void 0&&(m=new Wo(o),wh(t,m)),t=m}}}var Yi=class{constructor(e,t){this.seq=[],this.map={};let n=e.getProgramParameter(t,e.ACTIVE_UNIFORMS);for(let r=0;r<n;++r){let s=e.getActiveUniform(t,r),a=e.getUniformLocation(t,s.name);jv(s,a,this)}}setValue(e,t,n,r){let s=this.map[t];s!==void 0&&s.setValue(e,n,r)}setOptional(e,t,n){let r=t[n];r!==void 0&&this.setValue(e,n,r)}static upload(e,t,n,r){for(let s=0,a=t.length;s!==a;++s){let o=t[s],l=n[o.id];l.needsUpdate!==!1&&o.setValue(e,l.value,r)}}static seqWithValue(e,t){let n=[];for(let r=0,s=e.length;r!==s;++r){let a=e[r];a.id in t&&n.push(a)}return n}};function Eh(i,e,t){let n=i.createShader(e);return i.shaderSource(n,t),i.compileShader(n),n}var Jv=37297,Qv=0;function e_(i,e){let t=i.split(`
`),n=[],r=Math.max(e-6,0),s=Math.min(e+6,t.length);for(let a=r;a<s;a++){let o=a+1;n.push(`${o===e?">":" "} ${o}: ${t[a]}`)}return n.join(`
`)}var Th=new He;function t_(i){et._getMatrix(Th,et.workingColorSpace,i);let e=`mat3( ${Th.elements.map(t=>t.toFixed(4))} )`;switch(et.getTransfer(i)){case Ws:return[e,"LinearTransferOETF"];case ct:return[e,"sRGBTransferOETF"];default:return console.warn("THREE.WebGLProgram: Unsupported color space: ",i),[e,"LinearTransferOETF"]}}function Ah(i,e,t){let n=i.getShaderParameter(e,i.COMPILE_STATUS),r=i.getShaderInfoLog(e).trim();if(n&&r==="")return"";let s=/ERROR: 0:(\d+)/.exec(r);if(s){let a=parseInt(s[1]);return t.toUpperCase()+`

`+r+`

`+e_(i.getShaderSource(e),a)}else return r}function n_(i,e){let t=t_(e);return[`vec4 ${i}( vec4 value ) {`,`	return ${t[1]}( vec4( value.rgb * ${t[0]}, value.a ) );`,"}"].join(`
`)}function i_(i,e){let t;switch(e){case df:t="Linear";break;case ff:t="Reinhard";break;case pf:t="Cineon";break;case mf:t="ACESFilmic";break;case vf:t="AgX";break;case _f:t="Neutral";break;case gf:t="Custom";break;default:console.warn("THREE.WebGLProgram: Unsupported toneMapping:",e),t="Linear"}return"vec3 "+i+"( vec3 color ) { return "+t+"ToneMapping( color ); }"}var ps=new X;function r_(){et.getLuminanceCoefficients(ps);let i=ps.x.toFixed(4),e=ps.y.toFixed(4),t=ps.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${i}, ${e}, ${t} );`,"	return dot( weights, rgb );","}"].join(`
`)}function s_(i){return[i.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",i.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(Mr).join(`
`)}function a_(i){let e=[];for(let t in i){let n=i[t];n!==!1&&e.push("#define "+t+" "+n)}return e.join(`
`)}function o_(i,e){let t={},n=i.getProgramParameter(e,i.ACTIVE_ATTRIBUTES);for(let r=0;r<n;r++){let s=i.getActiveAttrib(e,r),a=s.name,o=1;s.type===i.FLOAT_MAT2&&(o=2),s.type===i.FLOAT_MAT3&&(o=3),s.type===i.FLOAT_MAT4&&(o=4),t[a]={type:s.type,location:i.getAttribLocation(e,a),locationSize:o}}return t}function Mr(i){return i!==""}function Ch(i,e){let t=e.numSpotLightShadows+e.numSpotLightMaps-e.numSpotLightShadowsWithMaps;return i.replace(/NUM_DIR_LIGHTS/g,e.numDirLights).replace(/NUM_SPOT_LIGHTS/g,e.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,e.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,t).replace(/NUM_RECT_AREA_LIGHTS/g,e.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,e.numPointLights).replace(/NUM_HEMI_LIGHTS/g,e.numHemiLights).replace(/NUM_DIR_LIGHT_SHADOWS/g,e.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,e.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,e.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,e.numPointLightShadows)}function Rh(i,e){return i.replace(/NUM_CLIPPING_PLANES/g,e.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,e.numClippingPlanes-e.numClipIntersection)}var c_=/^[ \t]*#include +<([\w\d./]+)>/gm;function Xo(i){return i.replace(c_,h_)}var l_=new Map;function h_(i,e){let t=Ye[e];if(t===void 0){let n=l_.get(e);if(n!==void 0)t=Ye[n],console.warn('THREE.WebGLRenderer: Shader chunk "%s" has been deprecated. Use "%s" instead.',e,n);else throw new Error("Can not resolve #include <"+e+">")}return Xo(t)}var u_=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function Ph(i){return i.replace(u_,d_)}function d_(i,e,t,n){let r="";for(let s=parseInt(e);s<parseInt(t);s++)r+=n.replace(/\[\s*i\s*\]/g,"[ "+s+" ]").replace(/UNROLLED_LOOP_INDEX/g,s);return r}function Lh(i){let e=`precision ${i.precision} float;
	precision ${i.precision} int;
	precision ${i.precision} sampler2D;
	precision ${i.precision} samplerCube;
	precision ${i.precision} sampler3D;
	precision ${i.precision} sampler2DArray;
	precision ${i.precision} sampler2DShadow;
	precision ${i.precision} samplerCubeShadow;
	precision ${i.precision} sampler2DArrayShadow;
	precision ${i.precision} isampler2D;
	precision ${i.precision} isampler3D;
	precision ${i.precision} isamplerCube;
	precision ${i.precision} isampler2DArray;
	precision ${i.precision} usampler2D;
	precision ${i.precision} usampler3D;
	precision ${i.precision} usamplerCube;
	precision ${i.precision} usampler2DArray;
	`;return i.precision==="highp"?e+=`
#define HIGH_PRECISION`:i.precision==="mediump"?e+=`
#define MEDIUM_PRECISION`:i.precision==="lowp"&&(e+=`
#define LOW_PRECISION`),e}function f_(i){let e="SHADOWMAP_TYPE_BASIC";return i.shadowMapType===kh?e="SHADOWMAP_TYPE_PCF":i.shadowMapType===Wd?e="SHADOWMAP_TYPE_PCF_SOFT":i.shadowMapType===wn&&(e="SHADOWMAP_TYPE_VSM"),e}function p_(i){let e="ENVMAP_TYPE_CUBE";if(i.envMap)switch(i.envMapMode){case $i:case Ki:e="ENVMAP_TYPE_CUBE";break;case Hs:e="ENVMAP_TYPE_CUBE_UV";break}return e}function m_(i){let e="ENVMAP_MODE_REFLECTION";if(i.envMap)switch(i.envMapMode){case Ki:e="ENVMAP_MODE_REFRACTION";break}return e}function g_(i){let e="ENVMAP_BLENDING_NONE";if(i.envMap)switch(i.combine){case Bh:e="ENVMAP_BLENDING_MULTIPLY";break;case hf:e="ENVMAP_BLENDING_MIX";break;case uf:e="ENVMAP_BLENDING_ADD";break}return e}function v_(i){let e=i.envMapCubeUVHeight;if(e===null)return null;let t=Math.log2(e)-2,n=1/e;return{texelWidth:1/(3*Math.max(Math.pow(2,t),7*16)),texelHeight:n,maxMip:t}}function __(i,e,t,n){let r=i.getContext(),s=t.defines,a=t.vertexShader,o=t.fragmentShader,l=f_(t),h=p_(t),d=m_(t),m=g_(t),f=v_(t),v=s_(t),S=a_(s),E=r.createProgram(),_,g,I=t.glslVersion?"#version "+t.glslVersion+`
`:"";t.isRawShaderMaterial?(_=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,S].filter(Mr).join(`
`),_.length>0&&(_+=`
`),g=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,S].filter(Mr).join(`
`),g.length>0&&(g+=`
`)):(_=[Lh(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,S,t.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",t.batching?"#define USE_BATCHING":"",t.batchingColor?"#define USE_BATCHING_COLOR":"",t.instancing?"#define USE_INSTANCING":"",t.instancingColor?"#define USE_INSTANCING_COLOR":"",t.instancingMorph?"#define USE_INSTANCING_MORPH":"",t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.map?"#define USE_MAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+d:"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.displacementMap?"#define USE_DISPLACEMENTMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.mapUv?"#define MAP_UV "+t.mapUv:"",t.alphaMapUv?"#define ALPHAMAP_UV "+t.alphaMapUv:"",t.lightMapUv?"#define LIGHTMAP_UV "+t.lightMapUv:"",t.aoMapUv?"#define AOMAP_UV "+t.aoMapUv:"",t.emissiveMapUv?"#define EMISSIVEMAP_UV "+t.emissiveMapUv:"",t.bumpMapUv?"#define BUMPMAP_UV "+t.bumpMapUv:"",t.normalMapUv?"#define NORMALMAP_UV "+t.normalMapUv:"",t.displacementMapUv?"#define DISPLACEMENTMAP_UV "+t.displacementMapUv:"",t.metalnessMapUv?"#define METALNESSMAP_UV "+t.metalnessMapUv:"",t.roughnessMapUv?"#define ROUGHNESSMAP_UV "+t.roughnessMapUv:"",t.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+t.anisotropyMapUv:"",t.clearcoatMapUv?"#define CLEARCOATMAP_UV "+t.clearcoatMapUv:"",t.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+t.clearcoatNormalMapUv:"",t.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+t.clearcoatRoughnessMapUv:"",t.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+t.iridescenceMapUv:"",t.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+t.iridescenceThicknessMapUv:"",t.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+t.sheenColorMapUv:"",t.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+t.sheenRoughnessMapUv:"",t.specularMapUv?"#define SPECULARMAP_UV "+t.specularMapUv:"",t.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+t.specularColorMapUv:"",t.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+t.specularIntensityMapUv:"",t.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+t.transmissionMapUv:"",t.thicknessMapUv?"#define THICKNESSMAP_UV "+t.thicknessMapUv:"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.flatShading?"#define FLAT_SHADED":"",t.skinning?"#define USE_SKINNING":"",t.morphTargets?"#define USE_MORPHTARGETS":"",t.morphNormals&&t.flatShading===!1?"#define USE_MORPHNORMALS":"",t.morphColors?"#define USE_MORPHCOLORS":"",t.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+t.morphTextureStride:"",t.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+t.morphTargetsCount:"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.sizeAttenuation?"#define USE_SIZEATTENUATION":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.logarithmicDepthBuffer?"#define USE_LOGDEPTHBUF":"",t.reverseDepthBuffer?"#define USE_REVERSEDEPTHBUF":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(Mr).join(`
`),g=[Lh(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,S,t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",t.map?"#define USE_MAP":"",t.matcap?"#define USE_MATCAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+h:"",t.envMap?"#define "+d:"",t.envMap?"#define "+m:"",f?"#define CUBEUV_TEXEL_WIDTH "+f.texelWidth:"",f?"#define CUBEUV_TEXEL_HEIGHT "+f.texelHeight:"",f?"#define CUBEUV_MAX_MIP "+f.maxMip+".0":"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoat?"#define USE_CLEARCOAT":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.dispersion?"#define USE_DISPERSION":"",t.iridescence?"#define USE_IRIDESCENCE":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaTest?"#define USE_ALPHATEST":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.sheen?"#define USE_SHEEN":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors||t.instancingColor||t.batchingColor?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.gradientMap?"#define USE_GRADIENTMAP":"",t.flatShading?"#define FLAT_SHADED":"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",t.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",t.logarithmicDepthBuffer?"#define USE_LOGDEPTHBUF":"",t.reverseDepthBuffer?"#define USE_REVERSEDEPTHBUF":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",t.toneMapping!==$n?"#define TONE_MAPPING":"",t.toneMapping!==$n?Ye.tonemapping_pars_fragment:"",t.toneMapping!==$n?i_("toneMapping",t.toneMapping):"",t.dithering?"#define DITHERING":"",t.opaque?"#define OPAQUE":"",Ye.colorspace_pars_fragment,n_("linearToOutputTexel",t.outputColorSpace),r_(),t.useDepthPacking?"#define DEPTH_PACKING "+t.depthPacking:"",`
`].filter(Mr).join(`
`)),a=Xo(a),a=Ch(a,t),a=Rh(a,t),o=Xo(o),o=Ch(o,t),o=Rh(o,t),a=Ph(a),o=Ph(o),t.isRawShaderMaterial!==!0&&(I=`#version 300 es
`,_=[v,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+_,g=["#define varying in",t.glslVersion===Wl?"":"layout(location = 0) out highp vec4 pc_fragColor;",t.glslVersion===Wl?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+g);let P=I+_+a,C=I+g+o,H=Eh(r,r.VERTEX_SHADER,P),U=Eh(r,r.FRAGMENT_SHADER,C);r.attachShader(E,H),r.attachShader(E,U),t.index0AttributeName!==void 0?r.bindAttribLocation(E,0,t.index0AttributeName):t.morphTargets===!0&&r.bindAttribLocation(E,0,"position"),r.linkProgram(E);function N(F){if(i.debug.checkShaderErrors){let Q=r.getProgramInfoLog(E).trim(),Z=r.getShaderInfoLog(H).trim(),J=r.getShaderInfoLog(U).trim(),ie=!0,$=!0;if(r.getProgramParameter(E,r.LINK_STATUS)===!1)if(ie=!1,typeof i.debug.onShaderError=="function")i.debug.onShaderError(r,E,H,U);else{let ue=Ah(r,H,"vertex"),j=Ah(r,U,"fragment");console.error("THREE.WebGLProgram: Shader Error "+r.getError()+" - VALIDATE_STATUS "+r.getProgramParameter(E,r.VALIDATE_STATUS)+`

Material Name: `+F.name+`
Material Type: `+F.type+`

Program Info Log: `+Q+`
`+ue+`
`+j)}else Q!==""?console.warn("THREE.WebGLProgram: Program Info Log:",Q):(Z===""||J==="")&&($=!1);$&&(F.diagnostics={runnable:ie,programLog:Q,vertexShader:{log:Z,prefix:_},fragmentShader:{log:J,prefix:g}})}r.deleteShader(H),r.deleteShader(U),V=new Yi(r,E),L=o_(r,E)}let V;this.getUniforms=function(){return V===void 0&&N(this),V};let L;this.getAttributes=function(){return L===void 0&&N(this),L};let R=t.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return R===!1&&(R=r.getProgramParameter(E,Jv)),R},this.destroy=function(){n.releaseStatesOfProgram(this),r.deleteProgram(E),this.program=void 0},this.type=t.shaderType,this.name=t.shaderName,this.id=Qv++,this.cacheKey=e,this.usedTimes=1,this.program=E,this.vertexShader=H,this.fragmentShader=U,this}var y_=0,qo=class{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(e){let t=e.vertexShader,n=e.fragmentShader,r=this._getShaderStage(t),s=this._getShaderStage(n),a=this._getShaderCacheForMaterial(e);return a.has(r)===!1&&(a.add(r),r.usedTimes++),a.has(s)===!1&&(a.add(s),s.usedTimes++),this}remove(e){let t=this.materialCache.get(e);for(let n of t)n.usedTimes--,n.usedTimes===0&&this.shaderCache.delete(n.code);return this.materialCache.delete(e),this}getVertexShaderID(e){return this._getShaderStage(e.vertexShader).id}getFragmentShaderID(e){return this._getShaderStage(e.fragmentShader).id}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(e){let t=this.materialCache,n=t.get(e);return n===void 0&&(n=new Set,t.set(e,n)),n}_getShaderStage(e){let t=this.shaderCache,n=t.get(e);return n===void 0&&(n=new Yo(e),t.set(e,n)),n}},Yo=class{constructor(e){this.id=y_++,this.code=e,this.usedTimes=0}};function x_(i,e,t,n,r,s,a){let o=new Cs,l=new qo,h=new Set,d=[],m=r.logarithmicDepthBuffer,f=r.vertexTextures,v=r.precision,S={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distanceRGBA",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function E(L){return h.add(L),L===0?"uv":`uv${L}`}function _(L,R,F,Q,Z){let J=Q.fog,ie=Z.geometry,$=L.isMeshStandardMaterial?Q.environment:null,ue=(L.isMeshStandardMaterial?t:e).get(L.envMap||$),j=ue&&ue.mapping===Hs?ue.image.height:null,ge=S[L.type];L.precision!==null&&(v=r.getMaxPrecision(L.precision),v!==L.precision&&console.warn("THREE.WebGLProgram.getParameters:",L.precision,"not supported, using",v,"instead."));let _e=ie.morphAttributes.position||ie.morphAttributes.normal||ie.morphAttributes.color,Ce=_e!==void 0?_e.length:0,ke=0;ie.morphAttributes.position!==void 0&&(ke=1),ie.morphAttributes.normal!==void 0&&(ke=2),ie.morphAttributes.color!==void 0&&(ke=3);let We,re,de,te;if(ge){let nt=dn[ge];We=nt.vertexShader,re=nt.fragmentShader}else We=L.vertexShader,re=L.fragmentShader,l.update(L),de=l.getVertexShaderID(L),te=l.getFragmentShaderID(L);let W=i.getRenderTarget(),he=i.state.buffers.depth.getReversed(),Oe=Z.isInstancedMesh===!0,Xe=Z.isBatchedMesh===!0,ut=!!L.map,qe=!!L.matcap,it=!!ue,G=!!L.aoMap,Ut=!!L.lightMap,Ke=!!L.bumpMap,je=!!L.normalMap,Pe=!!L.displacementMap,ht=!!L.emissiveMap,De=!!L.metalnessMap,D=!!L.roughnessMap,T=L.anisotropy>0,q=L.clearcoat>0,oe=L.dispersion>0,le=L.iridescence>0,se=L.sheen>0,Le=L.transmission>0,be=T&&!!L.anisotropyMap,Ee=q&&!!L.clearcoatMap,Je=q&&!!L.clearcoatNormalMap,me=q&&!!L.clearcoatRoughnessMap,Te=le&&!!L.iridescenceMap,Ne=le&&!!L.iridescenceThicknessMap,Ue=se&&!!L.sheenColorMap,Ae=se&&!!L.sheenRoughnessMap,Ze=!!L.specularMap,Fe=!!L.specularColorMap,rt=!!L.specularIntensityMap,k=Le&&!!L.transmissionMap,xe=Le&&!!L.thicknessMap,ee=!!L.gradientMap,ae=!!L.alphaMap,Me=L.alphaTest>0,Se=!!L.alphaHash,Be=!!L.extensions,ft=$n;L.toneMapped&&(W===null||W.isXRRenderTarget===!0)&&(ft=i.toneMapping);let wt={shaderID:ge,shaderType:L.type,shaderName:L.name,vertexShader:We,fragmentShader:re,defines:L.defines,customVertexShaderID:de,customFragmentShaderID:te,isRawShaderMaterial:L.isRawShaderMaterial===!0,glslVersion:L.glslVersion,precision:v,batching:Xe,batchingColor:Xe&&Z._colorsTexture!==null,instancing:Oe,instancingColor:Oe&&Z.instanceColor!==null,instancingMorph:Oe&&Z.morphTexture!==null,supportsVertexTextures:f,outputColorSpace:W===null?i.outputColorSpace:W.isXRRenderTarget===!0?W.texture.colorSpace:ir,alphaToCoverage:!!L.alphaToCoverage,map:ut,matcap:qe,envMap:it,envMapMode:it&&ue.mapping,envMapCubeUVHeight:j,aoMap:G,lightMap:Ut,bumpMap:Ke,normalMap:je,displacementMap:f&&Pe,emissiveMap:ht,normalMapObjectSpace:je&&L.normalMapType===Mf,normalMapTangentSpace:je&&L.normalMapType===Sf,metalnessMap:De,roughnessMap:D,anisotropy:T,anisotropyMap:be,clearcoat:q,clearcoatMap:Ee,clearcoatNormalMap:Je,clearcoatRoughnessMap:me,dispersion:oe,iridescence:le,iridescenceMap:Te,iridescenceThicknessMap:Ne,sheen:se,sheenColorMap:Ue,sheenRoughnessMap:Ae,specularMap:Ze,specularColorMap:Fe,specularIntensityMap:rt,transmission:Le,transmissionMap:k,thicknessMap:xe,gradientMap:ee,opaque:L.transparent===!1&&L.blending===Wi&&L.alphaToCoverage===!1,alphaMap:ae,alphaTest:Me,alphaHash:Se,combine:L.combine,mapUv:ut&&E(L.map.channel),aoMapUv:G&&E(L.aoMap.channel),lightMapUv:Ut&&E(L.lightMap.channel),bumpMapUv:Ke&&E(L.bumpMap.channel),normalMapUv:je&&E(L.normalMap.channel),displacementMapUv:Pe&&E(L.displacementMap.channel),emissiveMapUv:ht&&E(L.emissiveMap.channel),metalnessMapUv:De&&E(L.metalnessMap.channel),roughnessMapUv:D&&E(L.roughnessMap.channel),anisotropyMapUv:be&&E(L.anisotropyMap.channel),clearcoatMapUv:Ee&&E(L.clearcoatMap.channel),clearcoatNormalMapUv:Je&&E(L.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:me&&E(L.clearcoatRoughnessMap.channel),iridescenceMapUv:Te&&E(L.iridescenceMap.channel),iridescenceThicknessMapUv:Ne&&E(L.iridescenceThicknessMap.channel),sheenColorMapUv:Ue&&E(L.sheenColorMap.channel),sheenRoughnessMapUv:Ae&&E(L.sheenRoughnessMap.channel),specularMapUv:Ze&&E(L.specularMap.channel),specularColorMapUv:Fe&&E(L.specularColorMap.channel),specularIntensityMapUv:rt&&E(L.specularIntensityMap.channel),transmissionMapUv:k&&E(L.transmissionMap.channel),thicknessMapUv:xe&&E(L.thicknessMap.channel),alphaMapUv:ae&&E(L.alphaMap.channel),vertexTangents:!!ie.attributes.tangent&&(je||T),vertexColors:L.vertexColors,vertexAlphas:L.vertexColors===!0&&!!ie.attributes.color&&ie.attributes.color.itemSize===4,pointsUvs:Z.isPoints===!0&&!!ie.attributes.uv&&(ut||ae),fog:!!J,useFog:L.fog===!0,fogExp2:!!J&&J.isFogExp2,flatShading:L.flatShading===!0,sizeAttenuation:L.sizeAttenuation===!0,logarithmicDepthBuffer:m,reverseDepthBuffer:he,skinning:Z.isSkinnedMesh===!0,morphTargets:ie.morphAttributes.position!==void 0,morphNormals:ie.morphAttributes.normal!==void 0,morphColors:ie.morphAttributes.color!==void 0,morphTargetsCount:Ce,morphTextureStride:ke,numDirLights:R.directional.length,numPointLights:R.point.length,numSpotLights:R.spot.length,numSpotLightMaps:R.spotLightMap.length,numRectAreaLights:R.rectArea.length,numHemiLights:R.hemi.length,numDirLightShadows:R.directionalShadowMap.length,numPointLightShadows:R.pointShadowMap.length,numSpotLightShadows:R.spotShadowMap.length,numSpotLightShadowsWithMaps:R.numSpotLightShadowsWithMaps,numLightProbes:R.numLightProbes,numClippingPlanes:a.numPlanes,numClipIntersection:a.numIntersection,dithering:L.dithering,shadowMapEnabled:i.shadowMap.enabled&&F.length>0,shadowMapType:i.shadowMap.type,toneMapping:ft,decodeVideoTexture:ut&&L.map.isVideoTexture===!0&&et.getTransfer(L.map.colorSpace)===ct,decodeVideoTextureEmissive:ht&&L.emissiveMap.isVideoTexture===!0&&et.getTransfer(L.emissiveMap.colorSpace)===ct,premultipliedAlpha:L.premultipliedAlpha,doubleSided:L.side===En,flipSided:L.side===kt,useDepthPacking:L.depthPacking>=0,depthPacking:L.depthPacking||0,index0AttributeName:L.index0AttributeName,extensionClipCullDistance:Be&&L.extensions.clipCullDistance===!0&&n.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(Be&&L.extensions.multiDraw===!0||Xe)&&n.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:n.has("KHR_parallel_shader_compile"),customProgramCacheKey:L.customProgramCacheKey()};return wt.vertexUv1s=h.has(1),wt.vertexUv2s=h.has(2),wt.vertexUv3s=h.has(3),h.clear(),wt}function g(L){let R=[];if(L.shaderID?R.push(L.shaderID):(R.push(L.customVertexShaderID),R.push(L.customFragmentShaderID)),L.defines!==void 0)for(let F in L.defines)R.push(F),R.push(L.defines[F]);return L.isRawShaderMaterial===!1&&(I(R,L),P(R,L),R.push(i.outputColorSpace)),R.push(L.customProgramCacheKey),R.join()}function I(L,R){L.push(R.precision),L.push(R.outputColorSpace),L.push(R.envMapMode),L.push(R.envMapCubeUVHeight),L.push(R.mapUv),L.push(R.alphaMapUv),L.push(R.lightMapUv),L.push(R.aoMapUv),L.push(R.bumpMapUv),L.push(R.normalMapUv),L.push(R.displacementMapUv),L.push(R.emissiveMapUv),L.push(R.metalnessMapUv),L.push(R.roughnessMapUv),L.push(R.anisotropyMapUv),L.push(R.clearcoatMapUv),L.push(R.clearcoatNormalMapUv),L.push(R.clearcoatRoughnessMapUv),L.push(R.iridescenceMapUv),L.push(R.iridescenceThicknessMapUv),L.push(R.sheenColorMapUv),L.push(R.sheenRoughnessMapUv),L.push(R.specularMapUv),L.push(R.specularColorMapUv),L.push(R.specularIntensityMapUv),L.push(R.transmissionMapUv),L.push(R.thicknessMapUv),L.push(R.combine),L.push(R.fogExp2),L.push(R.sizeAttenuation),L.push(R.morphTargetsCount),L.push(R.morphAttributeCount),L.push(R.numDirLights),L.push(R.numPointLights),L.push(R.numSpotLights),L.push(R.numSpotLightMaps),L.push(R.numHemiLights),L.push(R.numRectAreaLights),L.push(R.numDirLightShadows),L.push(R.numPointLightShadows),L.push(R.numSpotLightShadows),L.push(R.numSpotLightShadowsWithMaps),L.push(R.numLightProbes),L.push(R.shadowMapType),L.push(R.toneMapping),L.push(R.numClippingPlanes),L.push(R.numClipIntersection),L.push(R.depthPacking)}function P(L,R){o.disableAll(),R.supportsVertexTextures&&o.enable(0),R.instancing&&o.enable(1),R.instancingColor&&o.enable(2),R.instancingMorph&&o.enable(3),R.matcap&&o.enable(4),R.envMap&&o.enable(5),R.normalMapObjectSpace&&o.enable(6),R.normalMapTangentSpace&&o.enable(7),R.clearcoat&&o.enable(8),R.iridescence&&o.enable(9),R.alphaTest&&o.enable(10),R.vertexColors&&o.enable(11),R.vertexAlphas&&o.enable(12),R.vertexUv1s&&o.enable(13),R.vertexUv2s&&o.enable(14),R.vertexUv3s&&o.enable(15),R.vertexTangents&&o.enable(16),R.anisotropy&&o.enable(17),R.alphaHash&&o.enable(18),R.batching&&o.enable(19),R.dispersion&&o.enable(20),R.batchingColor&&o.enable(21),L.push(o.mask),o.disableAll(),R.fog&&o.enable(0),R.useFog&&o.enable(1),R.flatShading&&o.enable(2),R.logarithmicDepthBuffer&&o.enable(3),R.reverseDepthBuffer&&o.enable(4),R.skinning&&o.enable(5),R.morphTargets&&o.enable(6),R.morphNormals&&o.enable(7),R.morphColors&&o.enable(8),R.premultipliedAlpha&&o.enable(9),R.shadowMapEnabled&&o.enable(10),R.doubleSided&&o.enable(11),R.flipSided&&o.enable(12),R.useDepthPacking&&o.enable(13),R.dithering&&o.enable(14),R.transmission&&o.enable(15),R.sheen&&o.enable(16),R.opaque&&o.enable(17),R.pointsUvs&&o.enable(18),R.decodeVideoTexture&&o.enable(19),R.decodeVideoTextureEmissive&&o.enable(20),R.alphaToCoverage&&o.enable(21),L.push(o.mask)}function C(L){let R=S[L.type],F;if(R){let Q=dn[R];F=hp.clone(Q.uniforms)}else F=L.uniforms;return F}function H(L,R){let F;for(let Q=0,Z=d.length;Q<Z;Q++){let J=d[Q];if(J.cacheKey===R){F=J,++F.usedTimes;break}}return F===void 0&&(F=new __(i,R,L,s),d.push(F)),F}function U(L){if(--L.usedTimes===0){let R=d.indexOf(L);d[R]=d[d.length-1],d.pop(),L.destroy()}}function N(L){l.remove(L)}function V(){l.dispose()}return{getParameters:_,getProgramCacheKey:g,getUniforms:C,acquireProgram:H,releaseProgram:U,releaseShaderCache:N,programs:d,dispose:V}}function b_(){let i=new WeakMap;function e(a){return i.has(a)}function t(a){let o=i.get(a);return o===void 0&&(o={},i.set(a,o)),o}function n(a){i.delete(a)}function r(a,o,l){i.get(a)[o]=l}function s(){i=new WeakMap}return{has:e,get:t,remove:n,update:r,dispose:s}}function S_(i,e){return i.groupOrder!==e.groupOrder?i.groupOrder-e.groupOrder:i.renderOrder!==e.renderOrder?i.renderOrder-e.renderOrder:i.material.id!==e.material.id?i.material.id-e.material.id:i.z!==e.z?i.z-e.z:i.id-e.id}function Ih(i,e){return i.groupOrder!==e.groupOrder?i.groupOrder-e.groupOrder:i.renderOrder!==e.renderOrder?i.renderOrder-e.renderOrder:i.z!==e.z?e.z-i.z:i.id-e.id}function Dh(){let i=[],e=0,t=[],n=[],r=[];function s(){e=0,t.length=0,n.length=0,r.length=0}function a(m,f,v,S,E,_){let g=i[e];return g===void 0?(g={id:m.id,object:m,geometry:f,material:v,groupOrder:S,renderOrder:m.renderOrder,z:E,group:_},i[e]=g):(g.id=m.id,g.object=m,g.geometry=f,g.material=v,g.groupOrder=S,g.renderOrder=m.renderOrder,g.z=E,g.group=_),e++,g}function o(m,f,v,S,E,_){let g=a(m,f,v,S,E,_);v.transmission>0?n.push(g):v.transparent===!0?r.push(g):t.push(g)}function l(m,f,v,S,E,_){let g=a(m,f,v,S,E,_);v.transmission>0?n.unshift(g):v.transparent===!0?r.unshift(g):t.unshift(g)}function h(m,f){t.length>1&&t.sort(m||S_),n.length>1&&n.sort(f||Ih),r.length>1&&r.sort(f||Ih)}function d(){for(let m=e,f=i.length;m<f;m++){let v=i[m];if(v.id===null)break;v.id=null,v.object=null,v.geometry=null,v.material=null,v.group=null}}return{opaque:t,transmissive:n,transparent:r,init:s,push:o,unshift:l,finish:d,sort:h}}function M_(){let i=new WeakMap;function e(n,r){let s=i.get(n),a;return s===void 0?(a=new Dh,i.set(n,[a])):r>=s.length?(a=new Dh,s.push(a)):a=s[r],a}function t(){i=new WeakMap}return{get:e,dispose:t}}function w_(){let i={};return{get:function(e){if(i[e.id]!==void 0)return i[e.id];let t;switch(e.type){case"DirectionalLight":t={direction:new X,color:new tt};break;case"SpotLight":t={position:new X,direction:new X,color:new tt,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":t={position:new X,color:new tt,distance:0,decay:0};break;case"HemisphereLight":t={direction:new X,skyColor:new tt,groundColor:new tt};break;case"RectAreaLight":t={color:new tt,position:new X,halfWidth:new X,halfHeight:new X};break}return i[e.id]=t,t}}}function E_(){let i={};return{get:function(e){if(i[e.id]!==void 0)return i[e.id];let t;switch(e.type){case"DirectionalLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new $e};break;case"SpotLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new $e};break;case"PointLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new $e,shadowCameraNear:1,shadowCameraFar:1e3};break}return i[e.id]=t,t}}}var T_=0;function A_(i,e){return(e.castShadow?2:0)-(i.castShadow?2:0)+(e.map?1:0)-(i.map?1:0)}function C_(i){let e=new w_,t=E_(),n={version:0,hash:{directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let h=0;h<9;h++)n.probe.push(new X);let r=new X,s=new _t,a=new _t;function o(h){let d=0,m=0,f=0;for(let L=0;L<9;L++)n.probe[L].set(0,0,0);let v=0,S=0,E=0,_=0,g=0,I=0,P=0,C=0,H=0,U=0,N=0;h.sort(A_);for(let L=0,R=h.length;L<R;L++){let F=h[L],Q=F.color,Z=F.intensity,J=F.distance,ie=F.shadow&&F.shadow.map?F.shadow.map.texture:null;if(F.isAmbientLight)d+=Q.r*Z,m+=Q.g*Z,f+=Q.b*Z;else if(F.isLightProbe){for(let $=0;$<9;$++)n.probe[$].addScaledVector(F.sh.coefficients[$],Z);N++}else if(F.isDirectionalLight){let $=e.get(F);if($.color.copy(F.color).multiplyScalar(F.intensity),F.castShadow){let ue=F.shadow,j=t.get(F);j.shadowIntensity=ue.intensity,j.shadowBias=ue.bias,j.shadowNormalBias=ue.normalBias,j.shadowRadius=ue.radius,j.shadowMapSize=ue.mapSize,n.directionalShadow[v]=j,n.directionalShadowMap[v]=ie,n.directionalShadowMatrix[v]=F.shadow.matrix,I++}n.directional[v]=$,v++}else if(F.isSpotLight){let $=e.get(F);$.position.setFromMatrixPosition(F.matrixWorld),$.color.copy(Q).multiplyScalar(Z),$.distance=J,$.coneCos=Math.cos(F.angle),$.penumbraCos=Math.cos(F.angle*(1-F.penumbra)),$.decay=F.decay,n.spot[E]=$;let ue=F.shadow;if(F.map&&(n.spotLightMap[H]=F.map,H++,ue.updateMatrices(F),F.castShadow&&U++),n.spotLightMatrix[E]=ue.matrix,F.castShadow){let j=t.get(F);j.shadowIntensity=ue.intensity,j.shadowBias=ue.bias,j.shadowNormalBias=ue.normalBias,j.shadowRadius=ue.radius,j.shadowMapSize=ue.mapSize,n.spotShadow[E]=j,n.spotShadowMap[E]=ie,C++}E++}else if(F.isRectAreaLight){let $=e.get(F);$.color.copy(Q).multiplyScalar(Z),$.halfWidth.set(F.width*.5,0,0),$.halfHeight.set(0,F.height*.5,0),n.rectArea[_]=$,_++}else if(F.isPointLight){let $=e.get(F);if($.color.copy(F.color).multiplyScalar(F.intensity),$.distance=F.distance,$.decay=F.decay,F.castShadow){let ue=F.shadow,j=t.get(F);j.shadowIntensity=ue.intensity,j.shadowBias=ue.bias,j.shadowNormalBias=ue.normalBias,j.shadowRadius=ue.radius,j.shadowMapSize=ue.mapSize,j.shadowCameraNear=ue.camera.near,j.shadowCameraFar=ue.camera.far,n.pointShadow[S]=j,n.pointShadowMap[S]=ie,n.pointShadowMatrix[S]=F.shadow.matrix,P++}n.point[S]=$,S++}else if(F.isHemisphereLight){let $=e.get(F);$.skyColor.copy(F.color).multiplyScalar(Z),$.groundColor.copy(F.groundColor).multiplyScalar(Z),n.hemi[g]=$,g++}}_>0&&(i.has("OES_texture_float_linear")===!0?(n.rectAreaLTC1=ye.LTC_FLOAT_1,n.rectAreaLTC2=ye.LTC_FLOAT_2):(n.rectAreaLTC1=ye.LTC_HALF_1,n.rectAreaLTC2=ye.LTC_HALF_2)),n.ambient[0]=d,n.ambient[1]=m,n.ambient[2]=f;let V=n.hash;(V.directionalLength!==v||V.pointLength!==S||V.spotLength!==E||V.rectAreaLength!==_||V.hemiLength!==g||V.numDirectionalShadows!==I||V.numPointShadows!==P||V.numSpotShadows!==C||V.numSpotMaps!==H||V.numLightProbes!==N)&&(n.directional.length=v,n.spot.length=E,n.rectArea.length=_,n.point.length=S,n.hemi.length=g,n.directionalShadow.length=I,n.directionalShadowMap.length=I,n.pointShadow.length=P,n.pointShadowMap.length=P,n.spotShadow.length=C,n.spotShadowMap.length=C,n.directionalShadowMatrix.length=I,n.pointShadowMatrix.length=P,n.spotLightMatrix.length=C+H-U,n.spotLightMap.length=H,n.numSpotLightShadowsWithMaps=U,n.numLightProbes=N,V.directionalLength=v,V.pointLength=S,V.spotLength=E,V.rectAreaLength=_,V.hemiLength=g,V.numDirectionalShadows=I,V.numPointShadows=P,V.numSpotShadows=C,V.numSpotMaps=H,V.numLightProbes=N,n.version=T_++)}function l(h,d){let m=0,f=0,v=0,S=0,E=0,_=d.matrixWorldInverse;for(let g=0,I=h.length;g<I;g++){let P=h[g];if(P.isDirectionalLight){let C=n.directional[m];C.direction.setFromMatrixPosition(P.matrixWorld),r.setFromMatrixPosition(P.target.matrixWorld),C.direction.sub(r),C.direction.transformDirection(_),m++}else if(P.isSpotLight){let C=n.spot[v];C.position.setFromMatrixPosition(P.matrixWorld),C.position.applyMatrix4(_),C.direction.setFromMatrixPosition(P.matrixWorld),r.setFromMatrixPosition(P.target.matrixWorld),C.direction.sub(r),C.direction.transformDirection(_),v++}else if(P.isRectAreaLight){let C=n.rectArea[S];C.position.setFromMatrixPosition(P.matrixWorld),C.position.applyMatrix4(_),a.identity(),s.copy(P.matrixWorld),s.premultiply(_),a.extractRotation(s),C.halfWidth.set(P.width*.5,0,0),C.halfHeight.set(0,P.height*.5,0),C.halfWidth.applyMatrix4(a),C.halfHeight.applyMatrix4(a),S++}else if(P.isPointLight){let C=n.point[f];C.position.setFromMatrixPosition(P.matrixWorld),C.position.applyMatrix4(_),f++}else if(P.isHemisphereLight){let C=n.hemi[E];C.direction.setFromMatrixPosition(P.matrixWorld),C.direction.transformDirection(_),E++}}}return{setup:o,setupView:l,state:n}}function Nh(i){let e=new C_(i),t=[],n=[];function r(d){h.camera=d,t.length=0,n.length=0}function s(d){t.push(d)}function a(d){n.push(d)}function o(){e.setup(t)}function l(d){e.setupView(t,d)}let h={lightsArray:t,shadowsArray:n,camera:null,lights:e,transmissionRenderTarget:{}};return{init:r,state:h,setupLights:o,setupLightsView:l,pushLight:s,pushShadow:a}}function R_(i){let e=new WeakMap;function t(r,s=0){let a=e.get(r),o;return a===void 0?(o=new Nh(i),e.set(r,[o])):s>=a.length?(o=new Nh(i),a.push(o)):o=a[s],o}function n(){e=new WeakMap}return{get:t,dispose:n}}var Zo=class extends gi{static get type(){return"MeshDepthMaterial"}constructor(e){super(),this.isMeshDepthMaterial=!0,this.depthPacking=xf,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(e)}copy(e){return super.copy(e),this.depthPacking=e.depthPacking,this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this}},$o=class extends gi{static get type(){return"MeshDistanceMaterial"}constructor(e){super(),this.isMeshDistanceMaterial=!0,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(e)}copy(e){return super.copy(e),this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this}},P_=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,L_=`uniform sampler2D shadow_pass;
uniform vec2 resolution;
uniform float radius;
#include <packing>
void main() {
	const float samples = float( VSM_SAMPLES );
	float mean = 0.0;
	float squared_mean = 0.0;
	float uvStride = samples <= 1.0 ? 0.0 : 2.0 / ( samples - 1.0 );
	float uvStart = samples <= 1.0 ? 0.0 : - 1.0;
	for ( float i = 0.0; i < samples; i ++ ) {
		float uvOffset = uvStart + i * uvStride;
		#ifdef HORIZONTAL_PASS
			vec2 distribution = unpackRGBATo2Half( texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( uvOffset, 0.0 ) * radius ) / resolution ) );
			mean += distribution.x;
			squared_mean += distribution.y * distribution.y + distribution.x * distribution.x;
		#else
			float depth = unpackRGBAToDepth( texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( 0.0, uvOffset ) * radius ) / resolution ) );
			mean += depth;
			squared_mean += depth * depth;
		#endif
	}
	mean = mean / samples;
	squared_mean = squared_mean / samples;
	float std_dev = sqrt( squared_mean - mean * mean );
	gl_FragColor = pack2HalfToRGBA( vec2( mean, std_dev ) );
}`;function I_(i,e,t){let n=new Ns,r=new $e,s=new $e,a=new gt,o=new Zo({depthPacking:bf}),l=new $o,h={},d=t.maxTextureSize,m={[Kn]:kt,[kt]:Kn,[En]:En},f=new mn({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new $e},radius:{value:4}},vertexShader:P_,fragmentShader:L_}),v=f.clone();v.defines.HORIZONTAL_PASS=1;let S=new pn;S.setAttribute("position",new Zt(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));let E=new an(S,f),_=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=kh;let g=this.type;this.render=function(U,N,V){if(_.enabled===!1||_.autoUpdate===!1&&_.needsUpdate===!1||U.length===0)return;let L=i.getRenderTarget(),R=i.getActiveCubeFace(),F=i.getActiveMipmapLevel(),Q=i.state;Q.setBlending(Zn),Q.buffers.color.setClear(1,1,1,1),Q.buffers.depth.setTest(!0),Q.setScissorTest(!1);let Z=g!==wn&&this.type===wn,J=g===wn&&this.type!==wn;for(let ie=0,$=U.length;ie<$;ie++){let ue=U[ie],j=ue.shadow;if(j===void 0){console.warn("THREE.WebGLShadowMap:",ue,"has no shadow.");continue}if(j.autoUpdate===!1&&j.needsUpdate===!1)continue;r.copy(j.mapSize);let ge=j.getFrameExtents();if(r.multiply(ge),s.copy(j.mapSize),(r.x>d||r.y>d)&&(r.x>d&&(s.x=Math.floor(d/ge.x),r.x=s.x*ge.x,j.mapSize.x=s.x),r.y>d&&(s.y=Math.floor(d/ge.y),r.y=s.y*ge.y,j.mapSize.y=s.y)),j.map===null||Z===!0||J===!0){let Ce=this.type!==wn?{minFilter:on,magFilter:on}:{};j.map!==null&&j.map.dispose(),j.map=new Ln(r.x,r.y,Ce),j.map.texture.name=ue.name+".shadowMap",j.camera.updateProjectionMatrix()}i.setRenderTarget(j.map),i.clear();let _e=j.getViewportCount();for(let Ce=0;Ce<_e;Ce++){let ke=j.getViewport(Ce);a.set(s.x*ke.x,s.y*ke.y,s.x*ke.z,s.y*ke.w),Q.viewport(a),j.updateMatrices(ue,Ce),n=j.getFrustum(),C(N,V,j.camera,ue,this.type)}j.isPointLightShadow!==!0&&this.type===wn&&I(j,V),j.needsUpdate=!1}g=this.type,_.needsUpdate=!1,i.setRenderTarget(L,R,F)};function I(U,N){let V=e.update(E);f.defines.VSM_SAMPLES!==U.blurSamples&&(f.defines.VSM_SAMPLES=U.blurSamples,v.defines.VSM_SAMPLES=U.blurSamples,f.needsUpdate=!0,v.needsUpdate=!0),U.mapPass===null&&(U.mapPass=new Ln(r.x,r.y)),f.uniforms.shadow_pass.value=U.map.texture,f.uniforms.resolution.value=U.mapSize,f.uniforms.radius.value=U.radius,i.setRenderTarget(U.mapPass),i.clear(),i.renderBufferDirect(N,null,V,f,E,null),v.uniforms.shadow_pass.value=U.mapPass.texture,v.uniforms.resolution.value=U.mapSize,v.uniforms.radius.value=U.radius,i.setRenderTarget(U.map),i.clear(),i.renderBufferDirect(N,null,V,v,E,null)}function P(U,N,V,L){let R=null,F=V.isPointLight===!0?U.customDistanceMaterial:U.customDepthMaterial;if(F!==void 0)R=F;else if(R=V.isPointLight===!0?l:o,i.localClippingEnabled&&N.clipShadows===!0&&Array.isArray(N.clippingPlanes)&&N.clippingPlanes.length!==0||N.displacementMap&&N.displacementScale!==0||N.alphaMap&&N.alphaTest>0||N.map&&N.alphaTest>0){let Q=R.uuid,Z=N.uuid,J=h[Q];J===void 0&&(J={},h[Q]=J);let ie=J[Z];ie===void 0&&(ie=R.clone(),J[Z]=ie,N.addEventListener("dispose",H)),R=ie}if(R.visible=N.visible,R.wireframe=N.wireframe,L===wn?R.side=N.shadowSide!==null?N.shadowSide:N.side:R.side=N.shadowSide!==null?N.shadowSide:m[N.side],R.alphaMap=N.alphaMap,R.alphaTest=N.alphaTest,R.map=N.map,R.clipShadows=N.clipShadows,R.clippingPlanes=N.clippingPlanes,R.clipIntersection=N.clipIntersection,R.displacementMap=N.displacementMap,R.displacementScale=N.displacementScale,R.displacementBias=N.displacementBias,R.wireframeLinewidth=N.wireframeLinewidth,R.linewidth=N.linewidth,V.isPointLight===!0&&R.isMeshDistanceMaterial===!0){let Q=i.properties.get(R);Q.light=V}return R}function C(U,N,V,L,R){if(U.visible===!1)return;if(U.layers.test(N.layers)&&(U.isMesh||U.isLine||U.isPoints)&&(U.castShadow||U.receiveShadow&&R===wn)&&(!U.frustumCulled||n.intersectsObject(U))){U.modelViewMatrix.multiplyMatrices(V.matrixWorldInverse,U.matrixWorld);let Z=e.update(U),J=U.material;if(Array.isArray(J)){let ie=Z.groups;for(let $=0,ue=ie.length;$<ue;$++){let j=ie[$],ge=J[j.materialIndex];if(ge&&ge.visible){let _e=P(U,ge,L,R);U.onBeforeShadow(i,U,N,V,Z,_e,j),i.renderBufferDirect(V,null,Z,_e,U,j),U.onAfterShadow(i,U,N,V,Z,_e,j)}}}else if(J.visible){let ie=P(U,J,L,R);U.onBeforeShadow(i,U,N,V,Z,ie,null),i.renderBufferDirect(V,null,Z,ie,U,null),U.onAfterShadow(i,U,N,V,Z,ie,null)}}let Q=U.children;for(let Z=0,J=Q.length;Z<J;Z++)C(Q[Z],N,V,L,R)}function H(U){U.target.removeEventListener("dispose",H);for(let V in h){let L=h[V],R=U.target.uuid;R in L&&(L[R].dispose(),delete L[R])}}}var D_={[ja]:Ja,[Qa]:no,[eo]:io,[Zi]:to,[Ja]:ja,[no]:Qa,[io]:eo,[to]:Zi};function N_(i,e){function t(){let k=!1,xe=new gt,ee=null,ae=new gt(0,0,0,0);return{setMask:function(Me){ee!==Me&&!k&&(i.colorMask(Me,Me,Me,Me),ee=Me)},setLocked:function(Me){k=Me},setClear:function(Me,Se,Be,ft,wt){wt===!0&&(Me*=ft,Se*=ft,Be*=ft),xe.set(Me,Se,Be,ft),ae.equals(xe)===!1&&(i.clearColor(Me,Se,Be,ft),ae.copy(xe))},reset:function(){k=!1,ee=null,ae.set(-1,0,0,0)}}}function n(){let k=!1,xe=!1,ee=null,ae=null,Me=null;return{setReversed:function(Se){if(xe!==Se){let Be=e.get("EXT_clip_control");xe?Be.clipControlEXT(Be.LOWER_LEFT_EXT,Be.ZERO_TO_ONE_EXT):Be.clipControlEXT(Be.LOWER_LEFT_EXT,Be.NEGATIVE_ONE_TO_ONE_EXT);let ft=Me;Me=null,this.setClear(ft)}xe=Se},getReversed:function(){return xe},setTest:function(Se){Se?W(i.DEPTH_TEST):he(i.DEPTH_TEST)},setMask:function(Se){ee!==Se&&!k&&(i.depthMask(Se),ee=Se)},setFunc:function(Se){if(xe&&(Se=D_[Se]),ae!==Se){switch(Se){case ja:i.depthFunc(i.NEVER);break;case Ja:i.depthFunc(i.ALWAYS);break;case Qa:i.depthFunc(i.LESS);break;case Zi:i.depthFunc(i.LEQUAL);break;case eo:i.depthFunc(i.EQUAL);break;case to:i.depthFunc(i.GEQUAL);break;case no:i.depthFunc(i.GREATER);break;case io:i.depthFunc(i.NOTEQUAL);break;default:i.depthFunc(i.LEQUAL)}ae=Se}},setLocked:function(Se){k=Se},setClear:function(Se){Me!==Se&&(xe&&(Se=1-Se),i.clearDepth(Se),Me=Se)},reset:function(){k=!1,ee=null,ae=null,Me=null,xe=!1}}}function r(){let k=!1,xe=null,ee=null,ae=null,Me=null,Se=null,Be=null,ft=null,wt=null;return{setTest:function(nt){k||(nt?W(i.STENCIL_TEST):he(i.STENCIL_TEST))},setMask:function(nt){xe!==nt&&!k&&(i.stencilMask(nt),xe=nt)},setFunc:function(nt,zt,Ht){(ee!==nt||ae!==zt||Me!==Ht)&&(i.stencilFunc(nt,zt,Ht),ee=nt,ae=zt,Me=Ht)},setOp:function(nt,zt,Ht){(Se!==nt||Be!==zt||ft!==Ht)&&(i.stencilOp(nt,zt,Ht),Se=nt,Be=zt,ft=Ht)},setLocked:function(nt){k=nt},setClear:function(nt){wt!==nt&&(i.clearStencil(nt),wt=nt)},reset:function(){k=!1,xe=null,ee=null,ae=null,Me=null,Se=null,Be=null,ft=null,wt=null}}}let s=new t,a=new n,o=new r,l=new WeakMap,h=new WeakMap,d={},m={},f=new WeakMap,v=[],S=null,E=!1,_=null,g=null,I=null,P=null,C=null,H=null,U=null,N=new tt(0,0,0),V=0,L=!1,R=null,F=null,Q=null,Z=null,J=null,ie=i.getParameter(i.MAX_COMBINED_TEXTURE_IMAGE_UNITS),$=!1,ue=0,j=i.getParameter(i.VERSION);j.indexOf("WebGL")!==-1?(ue=parseFloat(/^WebGL (\d)/.exec(j)[1]),$=ue>=1):j.indexOf("OpenGL ES")!==-1&&(ue=parseFloat(/^OpenGL ES (\d)/.exec(j)[1]),$=ue>=2);let ge=null,_e={},Ce=i.getParameter(i.SCISSOR_BOX),ke=i.getParameter(i.VIEWPORT),We=new gt().fromArray(Ce),re=new gt().fromArray(ke);function de(k,xe,ee,ae){let Me=new Uint8Array(4),Se=i.createTexture();i.bindTexture(k,Se),i.texParameteri(k,i.TEXTURE_MIN_FILTER,i.NEAREST),i.texParameteri(k,i.TEXTURE_MAG_FILTER,i.NEAREST);for(let Be=0;Be<ee;Be++)k===i.TEXTURE_3D||k===i.TEXTURE_2D_ARRAY?i.texImage3D(xe,0,i.RGBA,1,1,ae,0,i.RGBA,i.UNSIGNED_BYTE,Me):i.texImage2D(xe+Be,0,i.RGBA,1,1,0,i.RGBA,i.UNSIGNED_BYTE,Me);return Se}let te={};te[i.TEXTURE_2D]=de(i.TEXTURE_2D,i.TEXTURE_2D,1),te[i.TEXTURE_CUBE_MAP]=de(i.TEXTURE_CUBE_MAP,i.TEXTURE_CUBE_MAP_POSITIVE_X,6),te[i.TEXTURE_2D_ARRAY]=de(i.TEXTURE_2D_ARRAY,i.TEXTURE_2D_ARRAY,1,1),te[i.TEXTURE_3D]=de(i.TEXTURE_3D,i.TEXTURE_3D,1,1),s.setClear(0,0,0,1),a.setClear(1),o.setClear(0),W(i.DEPTH_TEST),a.setFunc(Zi),Ke(!1),je(Ul),W(i.CULL_FACE),G(Zn);function W(k){d[k]!==!0&&(i.enable(k),d[k]=!0)}function he(k){d[k]!==!1&&(i.disable(k),d[k]=!1)}function Oe(k,xe){return m[k]!==xe?(i.bindFramebuffer(k,xe),m[k]=xe,k===i.DRAW_FRAMEBUFFER&&(m[i.FRAMEBUFFER]=xe),k===i.FRAMEBUFFER&&(m[i.DRAW_FRAMEBUFFER]=xe),!0):!1}function Xe(k,xe){let ee=v,ae=!1;if(k){ee=f.get(xe),ee===void 0&&(ee=[],f.set(xe,ee));let Me=k.textures;if(ee.length!==Me.length||ee[0]!==i.COLOR_ATTACHMENT0){for(let Se=0,Be=Me.length;Se<Be;Se++)ee[Se]=i.COLOR_ATTACHMENT0+Se;ee.length=Me.length,ae=!0}}else ee[0]!==i.BACK&&(ee[0]=i.BACK,ae=!0);ae&&i.drawBuffers(ee)}function ut(k){return S!==k?(i.useProgram(k),S=k,!0):!1}let qe={[hi]:i.FUNC_ADD,[qd]:i.FUNC_SUBTRACT,[Yd]:i.FUNC_REVERSE_SUBTRACT};qe[Zd]=i.MIN,qe[$d]=i.MAX;let it={[Kd]:i.ZERO,[jd]:i.ONE,[Jd]:i.SRC_COLOR,[$a]:i.SRC_ALPHA,[sf]:i.SRC_ALPHA_SATURATE,[nf]:i.DST_COLOR,[ef]:i.DST_ALPHA,[Qd]:i.ONE_MINUS_SRC_COLOR,[Ka]:i.ONE_MINUS_SRC_ALPHA,[rf]:i.ONE_MINUS_DST_COLOR,[tf]:i.ONE_MINUS_DST_ALPHA,[af]:i.CONSTANT_COLOR,[of]:i.ONE_MINUS_CONSTANT_COLOR,[cf]:i.CONSTANT_ALPHA,[lf]:i.ONE_MINUS_CONSTANT_ALPHA};function G(k,xe,ee,ae,Me,Se,Be,ft,wt,nt){if(k===Zn){E===!0&&(he(i.BLEND),E=!1);return}if(E===!1&&(W(i.BLEND),E=!0),k!==Xd){if(k!==_||nt!==L){if((g!==hi||C!==hi)&&(i.blendEquation(i.FUNC_ADD),g=hi,C=hi),nt)switch(k){case Wi:i.blendFuncSeparate(i.ONE,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Fl:i.blendFunc(i.ONE,i.ONE);break;case Ol:i.blendFuncSeparate(i.ZERO,i.ONE_MINUS_SRC_COLOR,i.ZERO,i.ONE);break;case kl:i.blendFuncSeparate(i.ZERO,i.SRC_COLOR,i.ZERO,i.SRC_ALPHA);break;default:console.error("THREE.WebGLState: Invalid blending: ",k);break}else switch(k){case Wi:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Fl:i.blendFunc(i.SRC_ALPHA,i.ONE);break;case Ol:i.blendFuncSeparate(i.ZERO,i.ONE_MINUS_SRC_COLOR,i.ZERO,i.ONE);break;case kl:i.blendFunc(i.ZERO,i.SRC_COLOR);break;default:console.error("THREE.WebGLState: Invalid blending: ",k);break}I=null,P=null,H=null,U=null,N.set(0,0,0),V=0,_=k,L=nt}return}Me=Me||xe,Se=Se||ee,Be=Be||ae,(xe!==g||Me!==C)&&(i.blendEquationSeparate(qe[xe],qe[Me]),g=xe,C=Me),(ee!==I||ae!==P||Se!==H||Be!==U)&&(i.blendFuncSeparate(it[ee],it[ae],it[Se],it[Be]),I=ee,P=ae,H=Se,U=Be),(ft.equals(N)===!1||wt!==V)&&(i.blendColor(ft.r,ft.g,ft.b,wt),N.copy(ft),V=wt),_=k,L=!1}function Ut(k,xe){k.side===En?he(i.CULL_FACE):W(i.CULL_FACE);let ee=k.side===kt;xe&&(ee=!ee),Ke(ee),k.blending===Wi&&k.transparent===!1?G(Zn):G(k.blending,k.blendEquation,k.blendSrc,k.blendDst,k.blendEquationAlpha,k.blendSrcAlpha,k.blendDstAlpha,k.blendColor,k.blendAlpha,k.premultipliedAlpha),a.setFunc(k.depthFunc),a.setTest(k.depthTest),a.setMask(k.depthWrite),s.setMask(k.colorWrite);let ae=k.stencilWrite;o.setTest(ae),ae&&(o.setMask(k.stencilWriteMask),o.setFunc(k.stencilFunc,k.stencilRef,k.stencilFuncMask),o.setOp(k.stencilFail,k.stencilZFail,k.stencilZPass)),ht(k.polygonOffset,k.polygonOffsetFactor,k.polygonOffsetUnits),k.alphaToCoverage===!0?W(i.SAMPLE_ALPHA_TO_COVERAGE):he(i.SAMPLE_ALPHA_TO_COVERAGE)}function Ke(k){R!==k&&(k?i.frontFace(i.CW):i.frontFace(i.CCW),R=k)}function je(k){k!==Vd?(W(i.CULL_FACE),k!==F&&(k===Ul?i.cullFace(i.BACK):k===Hd?i.cullFace(i.FRONT):i.cullFace(i.FRONT_AND_BACK))):he(i.CULL_FACE),F=k}function Pe(k){k!==Q&&($&&i.lineWidth(k),Q=k)}function ht(k,xe,ee){k?(W(i.POLYGON_OFFSET_FILL),(Z!==xe||J!==ee)&&(i.polygonOffset(xe,ee),Z=xe,J=ee)):he(i.POLYGON_OFFSET_FILL)}function De(k){k?W(i.SCISSOR_TEST):he(i.SCISSOR_TEST)}function D(k){k===void 0&&(k=i.TEXTURE0+ie-1),ge!==k&&(i.activeTexture(k),ge=k)}function T(k,xe,ee){ee===void 0&&(ge===null?ee=i.TEXTURE0+ie-1:ee=ge);let ae=_e[ee];ae===void 0&&(ae={type:void 0,texture:void 0},_e[ee]=ae),(ae.type!==k||ae.texture!==xe)&&(ge!==ee&&(i.activeTexture(ee),ge=ee),i.bindTexture(k,xe||te[k]),ae.type=k,ae.texture=xe)}function q(){let k=_e[ge];k!==void 0&&k.type!==void 0&&(i.bindTexture(k.type,null),k.type=void 0,k.texture=void 0)}function oe(){try{i.compressedTexImage2D.apply(i,arguments)}catch(k){console.error("THREE.WebGLState:",k)}}function le(){try{i.compressedTexImage3D.apply(i,arguments)}catch(k){console.error("THREE.WebGLState:",k)}}function se(){try{i.texSubImage2D.apply(i,arguments)}catch(k){console.error("THREE.WebGLState:",k)}}function Le(){try{i.texSubImage3D.apply(i,arguments)}catch(k){console.error("THREE.WebGLState:",k)}}function be(){try{i.compressedTexSubImage2D.apply(i,arguments)}catch(k){console.error("THREE.WebGLState:",k)}}function Ee(){try{i.compressedTexSubImage3D.apply(i,arguments)}catch(k){console.error("THREE.WebGLState:",k)}}function Je(){try{i.texStorage2D.apply(i,arguments)}catch(k){console.error("THREE.WebGLState:",k)}}function me(){try{i.texStorage3D.apply(i,arguments)}catch(k){console.error("THREE.WebGLState:",k)}}function Te(){try{i.texImage2D.apply(i,arguments)}catch(k){console.error("THREE.WebGLState:",k)}}function Ne(){try{i.texImage3D.apply(i,arguments)}catch(k){console.error("THREE.WebGLState:",k)}}function Ue(k){We.equals(k)===!1&&(i.scissor(k.x,k.y,k.z,k.w),We.copy(k))}function Ae(k){re.equals(k)===!1&&(i.viewport(k.x,k.y,k.z,k.w),re.copy(k))}function Ze(k,xe){let ee=h.get(xe);ee===void 0&&(ee=new WeakMap,h.set(xe,ee));let ae=ee.get(k);ae===void 0&&(ae=i.getUniformBlockIndex(xe,k.name),ee.set(k,ae))}function Fe(k,xe){let ae=h.get(xe).get(k);l.get(xe)!==ae&&(i.uniformBlockBinding(xe,ae,k.__bindingPointIndex),l.set(xe,ae))}function rt(){i.disable(i.BLEND),i.disable(i.CULL_FACE),i.disable(i.DEPTH_TEST),i.disable(i.POLYGON_OFFSET_FILL),i.disable(i.SCISSOR_TEST),i.disable(i.STENCIL_TEST),i.disable(i.SAMPLE_ALPHA_TO_COVERAGE),i.blendEquation(i.FUNC_ADD),i.blendFunc(i.ONE,i.ZERO),i.blendFuncSeparate(i.ONE,i.ZERO,i.ONE,i.ZERO),i.blendColor(0,0,0,0),i.colorMask(!0,!0,!0,!0),i.clearColor(0,0,0,0),i.depthMask(!0),i.depthFunc(i.LESS),a.setReversed(!1),i.clearDepth(1),i.stencilMask(4294967295),i.stencilFunc(i.ALWAYS,0,4294967295),i.stencilOp(i.KEEP,i.KEEP,i.KEEP),i.clearStencil(0),i.cullFace(i.BACK),i.frontFace(i.CCW),i.polygonOffset(0,0),i.activeTexture(i.TEXTURE0),i.bindFramebuffer(i.FRAMEBUFFER,null),i.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),i.bindFramebuffer(i.READ_FRAMEBUFFER,null),i.useProgram(null),i.lineWidth(1),i.scissor(0,0,i.canvas.width,i.canvas.height),i.viewport(0,0,i.canvas.width,i.canvas.height),d={},ge=null,_e={},m={},f=new WeakMap,v=[],S=null,E=!1,_=null,g=null,I=null,P=null,C=null,H=null,U=null,N=new tt(0,0,0),V=0,L=!1,R=null,F=null,Q=null,Z=null,J=null,We.set(0,0,i.canvas.width,i.canvas.height),re.set(0,0,i.canvas.width,i.canvas.height),s.reset(),a.reset(),o.reset()}return{buffers:{color:s,depth:a,stencil:o},enable:W,disable:he,bindFramebuffer:Oe,drawBuffers:Xe,useProgram:ut,setBlending:G,setMaterial:Ut,setFlipSided:Ke,setCullFace:je,setLineWidth:Pe,setPolygonOffset:ht,setScissorTest:De,activeTexture:D,bindTexture:T,unbindTexture:q,compressedTexImage2D:oe,compressedTexImage3D:le,texImage2D:Te,texImage3D:Ne,updateUBOMapping:Ze,uniformBlockBinding:Fe,texStorage2D:Je,texStorage3D:me,texSubImage2D:se,texSubImage3D:Le,compressedTexSubImage2D:be,compressedTexSubImage3D:Ee,scissor:Ue,viewport:Ae,reset:rt}}function Uh(i,e,t,n){let r=U_(n);switch(t){case Wh:return i*e;case qh:return i*e;case Yh:return i*e*2;case Zh:return i*e/r.components*r.byteLength;case pc:return i*e/r.components*r.byteLength;case $h:return i*e*2/r.components*r.byteLength;case mc:return i*e*2/r.components*r.byteLength;case Xh:return i*e*3/r.components*r.byteLength;case sn:return i*e*4/r.components*r.byteLength;case gc:return i*e*4/r.components*r.byteLength;case _s:case ys:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*8;case xs:case bs:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case lo:case uo:return Math.max(i,16)*Math.max(e,8)/4;case co:case ho:return Math.max(i,8)*Math.max(e,8)/2;case fo:case po:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*8;case mo:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case go:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case vo:return Math.floor((i+4)/5)*Math.floor((e+3)/4)*16;case _o:return Math.floor((i+4)/5)*Math.floor((e+4)/5)*16;case yo:return Math.floor((i+5)/6)*Math.floor((e+4)/5)*16;case xo:return Math.floor((i+5)/6)*Math.floor((e+5)/6)*16;case bo:return Math.floor((i+7)/8)*Math.floor((e+4)/5)*16;case So:return Math.floor((i+7)/8)*Math.floor((e+5)/6)*16;case Mo:return Math.floor((i+7)/8)*Math.floor((e+7)/8)*16;case wo:return Math.floor((i+9)/10)*Math.floor((e+4)/5)*16;case Eo:return Math.floor((i+9)/10)*Math.floor((e+5)/6)*16;case To:return Math.floor((i+9)/10)*Math.floor((e+7)/8)*16;case Ao:return Math.floor((i+9)/10)*Math.floor((e+9)/10)*16;case Co:return Math.floor((i+11)/12)*Math.floor((e+9)/10)*16;case Ro:return Math.floor((i+11)/12)*Math.floor((e+11)/12)*16;case Ss:case Po:case Lo:return Math.ceil(i/4)*Math.ceil(e/4)*16;case Kh:case Io:return Math.ceil(i/4)*Math.ceil(e/4)*8;case Do:case No:return Math.ceil(i/4)*Math.ceil(e/4)*16}throw new Error(`Unable to determine texture byte length for ${t} format.`)}function U_(i){switch(i){case Rn:case Gh:return{byteLength:1,components:1};case Ar:case Vh:case Ir:return{byteLength:2,components:1};case dc:case fc:return{byteLength:2,components:4};case mi:case uc:case Tn:return{byteLength:4,components:1};case Hh:return{byteLength:4,components:3}}throw new Error(`Unknown texture type ${i}.`)}function F_(i,e,t,n,r,s,a){let o=e.has("WEBGL_multisampled_render_to_texture")?e.get("WEBGL_multisampled_render_to_texture"):null,l=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),h=new $e,d=new WeakMap,m,f=new WeakMap,v=!1;try{v=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function S(D,T){return v?new OffscreenCanvas(D,T):Es("canvas")}function E(D,T,q){let oe=1,le=De(D);if((le.width>q||le.height>q)&&(oe=q/Math.max(le.width,le.height)),oe<1)if(typeof HTMLImageElement<"u"&&D instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&D instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&D instanceof ImageBitmap||typeof VideoFrame<"u"&&D instanceof VideoFrame){let se=Math.floor(oe*le.width),Le=Math.floor(oe*le.height);m===void 0&&(m=S(se,Le));let be=T?S(se,Le):m;return be.width=se,be.height=Le,be.getContext("2d").drawImage(D,0,0,se,Le),console.warn("THREE.WebGLRenderer: Texture has been resized from ("+le.width+"x"+le.height+") to ("+se+"x"+Le+")."),be}else return"data"in D&&console.warn("THREE.WebGLRenderer: Image in DataTexture is too big ("+le.width+"x"+le.height+")."),D;return D}function _(D){return D.generateMipmaps}function g(D){i.generateMipmap(D)}function I(D){return D.isWebGLCubeRenderTarget?i.TEXTURE_CUBE_MAP:D.isWebGL3DRenderTarget?i.TEXTURE_3D:D.isWebGLArrayRenderTarget||D.isCompressedArrayTexture?i.TEXTURE_2D_ARRAY:i.TEXTURE_2D}function P(D,T,q,oe,le=!1){if(D!==null){if(i[D]!==void 0)return i[D];console.warn("THREE.WebGLRenderer: Attempt to use non-existing WebGL internal format '"+D+"'")}let se=T;if(T===i.RED&&(q===i.FLOAT&&(se=i.R32F),q===i.HALF_FLOAT&&(se=i.R16F),q===i.UNSIGNED_BYTE&&(se=i.R8)),T===i.RED_INTEGER&&(q===i.UNSIGNED_BYTE&&(se=i.R8UI),q===i.UNSIGNED_SHORT&&(se=i.R16UI),q===i.UNSIGNED_INT&&(se=i.R32UI),q===i.BYTE&&(se=i.R8I),q===i.SHORT&&(se=i.R16I),q===i.INT&&(se=i.R32I)),T===i.RG&&(q===i.FLOAT&&(se=i.RG32F),q===i.HALF_FLOAT&&(se=i.RG16F),q===i.UNSIGNED_BYTE&&(se=i.RG8)),T===i.RG_INTEGER&&(q===i.UNSIGNED_BYTE&&(se=i.RG8UI),q===i.UNSIGNED_SHORT&&(se=i.RG16UI),q===i.UNSIGNED_INT&&(se=i.RG32UI),q===i.BYTE&&(se=i.RG8I),q===i.SHORT&&(se=i.RG16I),q===i.INT&&(se=i.RG32I)),T===i.RGB_INTEGER&&(q===i.UNSIGNED_BYTE&&(se=i.RGB8UI),q===i.UNSIGNED_SHORT&&(se=i.RGB16UI),q===i.UNSIGNED_INT&&(se=i.RGB32UI),q===i.BYTE&&(se=i.RGB8I),q===i.SHORT&&(se=i.RGB16I),q===i.INT&&(se=i.RGB32I)),T===i.RGBA_INTEGER&&(q===i.UNSIGNED_BYTE&&(se=i.RGBA8UI),q===i.UNSIGNED_SHORT&&(se=i.RGBA16UI),q===i.UNSIGNED_INT&&(se=i.RGBA32UI),q===i.BYTE&&(se=i.RGBA8I),q===i.SHORT&&(se=i.RGBA16I),q===i.INT&&(se=i.RGBA32I)),T===i.RGB&&q===i.UNSIGNED_INT_5_9_9_9_REV&&(se=i.RGB9_E5),T===i.RGBA){let Le=le?Ws:et.getTransfer(oe);q===i.FLOAT&&(se=i.RGBA32F),q===i.HALF_FLOAT&&(se=i.RGBA16F),q===i.UNSIGNED_BYTE&&(se=Le===ct?i.SRGB8_ALPHA8:i.RGBA8),q===i.UNSIGNED_SHORT_4_4_4_4&&(se=i.RGBA4),q===i.UNSIGNED_SHORT_5_5_5_1&&(se=i.RGB5_A1)}return(se===i.R16F||se===i.R32F||se===i.RG16F||se===i.RG32F||se===i.RGBA16F||se===i.RGBA32F)&&e.get("EXT_color_buffer_float"),se}function C(D,T){let q;return D?T===null||T===mi||T===ji?q=i.DEPTH24_STENCIL8:T===Tn?q=i.DEPTH32F_STENCIL8:T===Ar&&(q=i.DEPTH24_STENCIL8,console.warn("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):T===null||T===mi||T===ji?q=i.DEPTH_COMPONENT24:T===Tn?q=i.DEPTH_COMPONENT32F:T===Ar&&(q=i.DEPTH_COMPONENT16),q}function H(D,T){return _(D)===!0||D.isFramebufferTexture&&D.minFilter!==on&&D.minFilter!==fn?Math.log2(Math.max(T.width,T.height))+1:D.mipmaps!==void 0&&D.mipmaps.length>0?D.mipmaps.length:D.isCompressedTexture&&Array.isArray(D.image)?T.mipmaps.length:1}function U(D){let T=D.target;T.removeEventListener("dispose",U),V(T),T.isVideoTexture&&d.delete(T)}function N(D){let T=D.target;T.removeEventListener("dispose",N),R(T)}function V(D){let T=n.get(D);if(T.__webglInit===void 0)return;let q=D.source,oe=f.get(q);if(oe){let le=oe[T.__cacheKey];le.usedTimes--,le.usedTimes===0&&L(D),Object.keys(oe).length===0&&f.delete(q)}n.remove(D)}function L(D){let T=n.get(D);i.deleteTexture(T.__webglTexture);let q=D.source,oe=f.get(q);delete oe[T.__cacheKey],a.memory.textures--}function R(D){let T=n.get(D);if(D.depthTexture&&(D.depthTexture.dispose(),n.remove(D.depthTexture)),D.isWebGLCubeRenderTarget)for(let oe=0;oe<6;oe++){if(Array.isArray(T.__webglFramebuffer[oe]))for(let le=0;le<T.__webglFramebuffer[oe].length;le++)i.deleteFramebuffer(T.__webglFramebuffer[oe][le]);else i.deleteFramebuffer(T.__webglFramebuffer[oe]);T.__webglDepthbuffer&&i.deleteRenderbuffer(T.__webglDepthbuffer[oe])}else{if(Array.isArray(T.__webglFramebuffer))for(let oe=0;oe<T.__webglFramebuffer.length;oe++)i.deleteFramebuffer(T.__webglFramebuffer[oe]);else i.deleteFramebuffer(T.__webglFramebuffer);if(T.__webglDepthbuffer&&i.deleteRenderbuffer(T.__webglDepthbuffer),T.__webglMultisampledFramebuffer&&i.deleteFramebuffer(T.__webglMultisampledFramebuffer),T.__webglColorRenderbuffer)for(let oe=0;oe<T.__webglColorRenderbuffer.length;oe++)T.__webglColorRenderbuffer[oe]&&i.deleteRenderbuffer(T.__webglColorRenderbuffer[oe]);T.__webglDepthRenderbuffer&&i.deleteRenderbuffer(T.__webglDepthRenderbuffer)}let q=D.textures;for(let oe=0,le=q.length;oe<le;oe++){let se=n.get(q[oe]);se.__webglTexture&&(i.deleteTexture(se.__webglTexture),a.memory.textures--),n.remove(q[oe])}n.remove(D)}let F=0;function Q(){F=0}function Z(){let D=F;return D>=r.maxTextures&&console.warn("THREE.WebGLTextures: Trying to use "+D+" texture units while this GPU supports only "+r.maxTextures),F+=1,D}function J(D){let T=[];return T.push(D.wrapS),T.push(D.wrapT),T.push(D.wrapR||0),T.push(D.magFilter),T.push(D.minFilter),T.push(D.anisotropy),T.push(D.internalFormat),T.push(D.format),T.push(D.type),T.push(D.generateMipmaps),T.push(D.premultiplyAlpha),T.push(D.flipY),T.push(D.unpackAlignment),T.push(D.colorSpace),T.join()}function ie(D,T){let q=n.get(D);if(D.isVideoTexture&&Pe(D),D.isRenderTargetTexture===!1&&D.version>0&&q.__version!==D.version){let oe=D.image;if(oe===null)console.warn("THREE.WebGLRenderer: Texture marked for update but no image data found.");else if(oe.complete===!1)console.warn("THREE.WebGLRenderer: Texture marked for update but image is incomplete");else{re(q,D,T);return}}t.bindTexture(i.TEXTURE_2D,q.__webglTexture,i.TEXTURE0+T)}function $(D,T){let q=n.get(D);if(D.version>0&&q.__version!==D.version){re(q,D,T);return}t.bindTexture(i.TEXTURE_2D_ARRAY,q.__webglTexture,i.TEXTURE0+T)}function ue(D,T){let q=n.get(D);if(D.version>0&&q.__version!==D.version){re(q,D,T);return}t.bindTexture(i.TEXTURE_3D,q.__webglTexture,i.TEXTURE0+T)}function j(D,T){let q=n.get(D);if(D.version>0&&q.__version!==D.version){de(q,D,T);return}t.bindTexture(i.TEXTURE_CUBE_MAP,q.__webglTexture,i.TEXTURE0+T)}let ge={[ao]:i.REPEAT,[fi]:i.CLAMP_TO_EDGE,[oo]:i.MIRRORED_REPEAT},_e={[on]:i.NEAREST,[yf]:i.NEAREST_MIPMAP_NEAREST,[Zr]:i.NEAREST_MIPMAP_LINEAR,[fn]:i.LINEAR,[ba]:i.LINEAR_MIPMAP_NEAREST,[pi]:i.LINEAR_MIPMAP_LINEAR},Ce={[wf]:i.NEVER,[Pf]:i.ALWAYS,[Ef]:i.LESS,[jh]:i.LEQUAL,[Tf]:i.EQUAL,[Rf]:i.GEQUAL,[Af]:i.GREATER,[Cf]:i.NOTEQUAL};function ke(D,T){if(T.type===Tn&&e.has("OES_texture_float_linear")===!1&&(T.magFilter===fn||T.magFilter===ba||T.magFilter===Zr||T.magFilter===pi||T.minFilter===fn||T.minFilter===ba||T.minFilter===Zr||T.minFilter===pi)&&console.warn("THREE.WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),i.texParameteri(D,i.TEXTURE_WRAP_S,ge[T.wrapS]),i.texParameteri(D,i.TEXTURE_WRAP_T,ge[T.wrapT]),(D===i.TEXTURE_3D||D===i.TEXTURE_2D_ARRAY)&&i.texParameteri(D,i.TEXTURE_WRAP_R,ge[T.wrapR]),i.texParameteri(D,i.TEXTURE_MAG_FILTER,_e[T.magFilter]),i.texParameteri(D,i.TEXTURE_MIN_FILTER,_e[T.minFilter]),T.compareFunction&&(i.texParameteri(D,i.TEXTURE_COMPARE_MODE,i.COMPARE_REF_TO_TEXTURE),i.texParameteri(D,i.TEXTURE_COMPARE_FUNC,Ce[T.compareFunction])),e.has("EXT_texture_filter_anisotropic")===!0){if(T.magFilter===on||T.minFilter!==Zr&&T.minFilter!==pi||T.type===Tn&&e.has("OES_texture_float_linear")===!1)return;if(T.anisotropy>1||n.get(T).__currentAnisotropy){let q=e.get("EXT_texture_filter_anisotropic");i.texParameterf(D,q.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(T.anisotropy,r.getMaxAnisotropy())),n.get(T).__currentAnisotropy=T.anisotropy}}}function We(D,T){let q=!1;D.__webglInit===void 0&&(D.__webglInit=!0,T.addEventListener("dispose",U));let oe=T.source,le=f.get(oe);le===void 0&&(le={},f.set(oe,le));let se=J(T);if(se!==D.__cacheKey){le[se]===void 0&&(le[se]={texture:i.createTexture(),usedTimes:0},a.memory.textures++,q=!0),le[se].usedTimes++;let Le=le[D.__cacheKey];Le!==void 0&&(le[D.__cacheKey].usedTimes--,Le.usedTimes===0&&L(T)),D.__cacheKey=se,D.__webglTexture=le[se].texture}return q}function re(D,T,q){let oe=i.TEXTURE_2D;(T.isDataArrayTexture||T.isCompressedArrayTexture)&&(oe=i.TEXTURE_2D_ARRAY),T.isData3DTexture&&(oe=i.TEXTURE_3D);let le=We(D,T),se=T.source;t.bindTexture(oe,D.__webglTexture,i.TEXTURE0+q);let Le=n.get(se);if(se.version!==Le.__version||le===!0){t.activeTexture(i.TEXTURE0+q);let be=et.getPrimaries(et.workingColorSpace),Ee=T.colorSpace===Yn?null:et.getPrimaries(T.colorSpace),Je=T.colorSpace===Yn||be===Ee?i.NONE:i.BROWSER_DEFAULT_WEBGL;i.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,T.flipY),i.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,T.premultiplyAlpha),i.pixelStorei(i.UNPACK_ALIGNMENT,T.unpackAlignment),i.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,Je);let me=E(T.image,!1,r.maxTextureSize);me=ht(T,me);let Te=s.convert(T.format,T.colorSpace),Ne=s.convert(T.type),Ue=P(T.internalFormat,Te,Ne,T.colorSpace,T.isVideoTexture);ke(oe,T);let Ae,Ze=T.mipmaps,Fe=T.isVideoTexture!==!0,rt=Le.__version===void 0||le===!0,k=se.dataReady,xe=H(T,me);if(T.isDepthTexture)Ue=C(T.format===Ji,T.type),rt&&(Fe?t.texStorage2D(i.TEXTURE_2D,1,Ue,me.width,me.height):t.texImage2D(i.TEXTURE_2D,0,Ue,me.width,me.height,0,Te,Ne,null));else if(T.isDataTexture)if(Ze.length>0){Fe&&rt&&t.texStorage2D(i.TEXTURE_2D,xe,Ue,Ze[0].width,Ze[0].height);for(let ee=0,ae=Ze.length;ee<ae;ee++)Ae=Ze[ee],Fe?k&&t.texSubImage2D(i.TEXTURE_2D,ee,0,0,Ae.width,Ae.height,Te,Ne,Ae.data):t.texImage2D(i.TEXTURE_2D,ee,Ue,Ae.width,Ae.height,0,Te,Ne,Ae.data);T.generateMipmaps=!1}else Fe?(rt&&t.texStorage2D(i.TEXTURE_2D,xe,Ue,me.width,me.height),k&&t.texSubImage2D(i.TEXTURE_2D,0,0,0,me.width,me.height,Te,Ne,me.data)):t.texImage2D(i.TEXTURE_2D,0,Ue,me.width,me.height,0,Te,Ne,me.data);else if(T.isCompressedTexture)if(T.isCompressedArrayTexture){Fe&&rt&&t.texStorage3D(i.TEXTURE_2D_ARRAY,xe,Ue,Ze[0].width,Ze[0].height,me.depth);for(let ee=0,ae=Ze.length;ee<ae;ee++)if(Ae=Ze[ee],T.format!==sn)if(Te!==null)if(Fe){if(k)if(T.layerUpdates.size>0){let Me=Uh(Ae.width,Ae.height,T.format,T.type);for(let Se of T.layerUpdates){let Be=Ae.data.subarray(Se*Me/Ae.data.BYTES_PER_ELEMENT,(Se+1)*Me/Ae.data.BYTES_PER_ELEMENT);t.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ee,0,0,Se,Ae.width,Ae.height,1,Te,Be)}T.clearLayerUpdates()}else t.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ee,0,0,0,Ae.width,Ae.height,me.depth,Te,Ae.data)}else t.compressedTexImage3D(i.TEXTURE_2D_ARRAY,ee,Ue,Ae.width,Ae.height,me.depth,0,Ae.data,0,0);else console.warn("THREE.WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else Fe?k&&t.texSubImage3D(i.TEXTURE_2D_ARRAY,ee,0,0,0,Ae.width,Ae.height,me.depth,Te,Ne,Ae.data):t.texImage3D(i.TEXTURE_2D_ARRAY,ee,Ue,Ae.width,Ae.height,me.depth,0,Te,Ne,Ae.data)}else{Fe&&rt&&t.texStorage2D(i.TEXTURE_2D,xe,Ue,Ze[0].width,Ze[0].height);for(let ee=0,ae=Ze.length;ee<ae;ee++)Ae=Ze[ee],T.format!==sn?Te!==null?Fe?k&&t.compressedTexSubImage2D(i.TEXTURE_2D,ee,0,0,Ae.width,Ae.height,Te,Ae.data):t.compressedTexImage2D(i.TEXTURE_2D,ee,Ue,Ae.width,Ae.height,0,Ae.data):console.warn("THREE.WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):Fe?k&&t.texSubImage2D(i.TEXTURE_2D,ee,0,0,Ae.width,Ae.height,Te,Ne,Ae.data):t.texImage2D(i.TEXTURE_2D,ee,Ue,Ae.width,Ae.height,0,Te,Ne,Ae.data)}else if(T.isDataArrayTexture)if(Fe){if(rt&&t.texStorage3D(i.TEXTURE_2D_ARRAY,xe,Ue,me.width,me.height,me.depth),k)if(T.layerUpdates.size>0){let ee=Uh(me.width,me.height,T.format,T.type);for(let ae of T.layerUpdates){let Me=me.data.subarray(ae*ee/me.data.BYTES_PER_ELEMENT,(ae+1)*ee/me.data.BYTES_PER_ELEMENT);t.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,ae,me.width,me.height,1,Te,Ne,Me)}T.clearLayerUpdates()}else t.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,0,me.width,me.height,me.depth,Te,Ne,me.data)}else t.texImage3D(i.TEXTURE_2D_ARRAY,0,Ue,me.width,me.height,me.depth,0,Te,Ne,me.data);else if(T.isData3DTexture)Fe?(rt&&t.texStorage3D(i.TEXTURE_3D,xe,Ue,me.width,me.height,me.depth),k&&t.texSubImage3D(i.TEXTURE_3D,0,0,0,0,me.width,me.height,me.depth,Te,Ne,me.data)):t.texImage3D(i.TEXTURE_3D,0,Ue,me.width,me.height,me.depth,0,Te,Ne,me.data);else if(T.isFramebufferTexture){if(rt)if(Fe)t.texStorage2D(i.TEXTURE_2D,xe,Ue,me.width,me.height);else{let ee=me.width,ae=me.height;for(let Me=0;Me<xe;Me++)t.texImage2D(i.TEXTURE_2D,Me,Ue,ee,ae,0,Te,Ne,null),ee>>=1,ae>>=1}}else if(Ze.length>0){if(Fe&&rt){let ee=De(Ze[0]);t.texStorage2D(i.TEXTURE_2D,xe,Ue,ee.width,ee.height)}for(let ee=0,ae=Ze.length;ee<ae;ee++)Ae=Ze[ee],Fe?k&&t.texSubImage2D(i.TEXTURE_2D,ee,0,0,Te,Ne,Ae):t.texImage2D(i.TEXTURE_2D,ee,Ue,Te,Ne,Ae);T.generateMipmaps=!1}else if(Fe){if(rt){let ee=De(me);t.texStorage2D(i.TEXTURE_2D,xe,Ue,ee.width,ee.height)}k&&t.texSubImage2D(i.TEXTURE_2D,0,0,0,Te,Ne,me)}else t.texImage2D(i.TEXTURE_2D,0,Ue,Te,Ne,me);_(T)&&g(oe),Le.__version=se.version,T.onUpdate&&T.onUpdate(T)}D.__version=T.version}function de(D,T,q){if(T.image.length!==6)return;let oe=We(D,T),le=T.source;t.bindTexture(i.TEXTURE_CUBE_MAP,D.__webglTexture,i.TEXTURE0+q);let se=n.get(le);if(le.version!==se.__version||oe===!0){t.activeTexture(i.TEXTURE0+q);let Le=et.getPrimaries(et.workingColorSpace),be=T.colorSpace===Yn?null:et.getPrimaries(T.colorSpace),Ee=T.colorSpace===Yn||Le===be?i.NONE:i.BROWSER_DEFAULT_WEBGL;i.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,T.flipY),i.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,T.premultiplyAlpha),i.pixelStorei(i.UNPACK_ALIGNMENT,T.unpackAlignment),i.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,Ee);let Je=T.isCompressedTexture||T.image[0].isCompressedTexture,me=T.image[0]&&T.image[0].isDataTexture,Te=[];for(let ae=0;ae<6;ae++)!Je&&!me?Te[ae]=E(T.image[ae],!0,r.maxCubemapSize):Te[ae]=me?T.image[ae].image:T.image[ae],Te[ae]=ht(T,Te[ae]);let Ne=Te[0],Ue=s.convert(T.format,T.colorSpace),Ae=s.convert(T.type),Ze=P(T.internalFormat,Ue,Ae,T.colorSpace),Fe=T.isVideoTexture!==!0,rt=se.__version===void 0||oe===!0,k=le.dataReady,xe=H(T,Ne);ke(i.TEXTURE_CUBE_MAP,T);let ee;if(Je){Fe&&rt&&t.texStorage2D(i.TEXTURE_CUBE_MAP,xe,Ze,Ne.width,Ne.height);for(let ae=0;ae<6;ae++){ee=Te[ae].mipmaps;for(let Me=0;Me<ee.length;Me++){let Se=ee[Me];T.format!==sn?Ue!==null?Fe?k&&t.compressedTexSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+ae,Me,0,0,Se.width,Se.height,Ue,Se.data):t.compressedTexImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+ae,Me,Ze,Se.width,Se.height,0,Se.data):console.warn("THREE.WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):Fe?k&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+ae,Me,0,0,Se.width,Se.height,Ue,Ae,Se.data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+ae,Me,Ze,Se.width,Se.height,0,Ue,Ae,Se.data)}}}else{if(ee=T.mipmaps,Fe&&rt){ee.length>0&&xe++;let ae=De(Te[0]);t.texStorage2D(i.TEXTURE_CUBE_MAP,xe,Ze,ae.width,ae.height)}for(let ae=0;ae<6;ae++)if(me){Fe?k&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+ae,0,0,0,Te[ae].width,Te[ae].height,Ue,Ae,Te[ae].data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+ae,0,Ze,Te[ae].width,Te[ae].height,0,Ue,Ae,Te[ae].data);for(let Me=0;Me<ee.length;Me++){let Be=ee[Me].image[ae].image;Fe?k&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+ae,Me+1,0,0,Be.width,Be.height,Ue,Ae,Be.data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+ae,Me+1,Ze,Be.width,Be.height,0,Ue,Ae,Be.data)}}else{Fe?k&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+ae,0,0,0,Ue,Ae,Te[ae]):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+ae,0,Ze,Ue,Ae,Te[ae]);for(let Me=0;Me<ee.length;Me++){let Se=ee[Me];Fe?k&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+ae,Me+1,0,0,Ue,Ae,Se.image[ae]):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+ae,Me+1,Ze,Ue,Ae,Se.image[ae])}}}_(T)&&g(i.TEXTURE_CUBE_MAP),se.__version=le.version,T.onUpdate&&T.onUpdate(T)}D.__version=T.version}function te(D,T,q,oe,le,se){let Le=s.convert(q.format,q.colorSpace),be=s.convert(q.type),Ee=P(q.internalFormat,Le,be,q.colorSpace),Je=n.get(T),me=n.get(q);if(me.__renderTarget=T,!Je.__hasExternalTextures){let Te=Math.max(1,T.width>>se),Ne=Math.max(1,T.height>>se);le===i.TEXTURE_3D||le===i.TEXTURE_2D_ARRAY?t.texImage3D(le,se,Ee,Te,Ne,T.depth,0,Le,be,null):t.texImage2D(le,se,Ee,Te,Ne,0,Le,be,null)}t.bindFramebuffer(i.FRAMEBUFFER,D),je(T)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,oe,le,me.__webglTexture,0,Ke(T)):(le===i.TEXTURE_2D||le>=i.TEXTURE_CUBE_MAP_POSITIVE_X&&le<=i.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&i.framebufferTexture2D(i.FRAMEBUFFER,oe,le,me.__webglTexture,se),t.bindFramebuffer(i.FRAMEBUFFER,null)}function W(D,T,q){if(i.bindRenderbuffer(i.RENDERBUFFER,D),T.depthBuffer){let oe=T.depthTexture,le=oe&&oe.isDepthTexture?oe.type:null,se=C(T.stencilBuffer,le),Le=T.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,be=Ke(T);je(T)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,be,se,T.width,T.height):q?i.renderbufferStorageMultisample(i.RENDERBUFFER,be,se,T.width,T.height):i.renderbufferStorage(i.RENDERBUFFER,se,T.width,T.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,Le,i.RENDERBUFFER,D)}else{let oe=T.textures;for(let le=0;le<oe.length;le++){let se=oe[le],Le=s.convert(se.format,se.colorSpace),be=s.convert(se.type),Ee=P(se.internalFormat,Le,be,se.colorSpace),Je=Ke(T);q&&je(T)===!1?i.renderbufferStorageMultisample(i.RENDERBUFFER,Je,Ee,T.width,T.height):je(T)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,Je,Ee,T.width,T.height):i.renderbufferStorage(i.RENDERBUFFER,Ee,T.width,T.height)}}i.bindRenderbuffer(i.RENDERBUFFER,null)}function he(D,T){if(T&&T.isWebGLCubeRenderTarget)throw new Error("Depth Texture with cube render targets is not supported");if(t.bindFramebuffer(i.FRAMEBUFFER,D),!(T.depthTexture&&T.depthTexture.isDepthTexture))throw new Error("renderTarget.depthTexture must be an instance of THREE.DepthTexture");let oe=n.get(T.depthTexture);oe.__renderTarget=T,(!oe.__webglTexture||T.depthTexture.image.width!==T.width||T.depthTexture.image.height!==T.height)&&(T.depthTexture.image.width=T.width,T.depthTexture.image.height=T.height,T.depthTexture.needsUpdate=!0),ie(T.depthTexture,0);let le=oe.__webglTexture,se=Ke(T);if(T.depthTexture.format===Xi)je(T)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,i.DEPTH_ATTACHMENT,i.TEXTURE_2D,le,0,se):i.framebufferTexture2D(i.FRAMEBUFFER,i.DEPTH_ATTACHMENT,i.TEXTURE_2D,le,0);else if(T.depthTexture.format===Ji)je(T)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,i.DEPTH_STENCIL_ATTACHMENT,i.TEXTURE_2D,le,0,se):i.framebufferTexture2D(i.FRAMEBUFFER,i.DEPTH_STENCIL_ATTACHMENT,i.TEXTURE_2D,le,0);else throw new Error("Unknown depthTexture format")}function Oe(D){let T=n.get(D),q=D.isWebGLCubeRenderTarget===!0;if(T.__boundDepthTexture!==D.depthTexture){let oe=D.depthTexture;if(T.__depthDisposeCallback&&T.__depthDisposeCallback(),oe){let le=()=>{delete T.__boundDepthTexture,delete T.__depthDisposeCallback,oe.removeEventListener("dispose",le)};oe.addEventListener("dispose",le),T.__depthDisposeCallback=le}T.__boundDepthTexture=oe}if(D.depthTexture&&!T.__autoAllocateDepthBuffer){if(q)throw new Error("target.depthTexture not supported in Cube render targets");he(T.__webglFramebuffer,D)}else if(q){T.__webglDepthbuffer=[];for(let oe=0;oe<6;oe++)if(t.bindFramebuffer(i.FRAMEBUFFER,T.__webglFramebuffer[oe]),T.__webglDepthbuffer[oe]===void 0)T.__webglDepthbuffer[oe]=i.createRenderbuffer(),W(T.__webglDepthbuffer[oe],D,!1);else{let le=D.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,se=T.__webglDepthbuffer[oe];i.bindRenderbuffer(i.RENDERBUFFER,se),i.framebufferRenderbuffer(i.FRAMEBUFFER,le,i.RENDERBUFFER,se)}}else if(t.bindFramebuffer(i.FRAMEBUFFER,T.__webglFramebuffer),T.__webglDepthbuffer===void 0)T.__webglDepthbuffer=i.createRenderbuffer(),W(T.__webglDepthbuffer,D,!1);else{let oe=D.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,le=T.__webglDepthbuffer;i.bindRenderbuffer(i.RENDERBUFFER,le),i.framebufferRenderbuffer(i.FRAMEBUFFER,oe,i.RENDERBUFFER,le)}t.bindFramebuffer(i.FRAMEBUFFER,null)}function Xe(D,T,q){let oe=n.get(D);T!==void 0&&te(oe.__webglFramebuffer,D,D.texture,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,0),q!==void 0&&Oe(D)}function ut(D){let T=D.texture,q=n.get(D),oe=n.get(T);D.addEventListener("dispose",N);let le=D.textures,se=D.isWebGLCubeRenderTarget===!0,Le=le.length>1;if(Le||(oe.__webglTexture===void 0&&(oe.__webglTexture=i.createTexture()),oe.__version=T.version,a.memory.textures++),se){q.__webglFramebuffer=[];for(let be=0;be<6;be++)if(T.mipmaps&&T.mipmaps.length>0){q.__webglFramebuffer[be]=[];for(let Ee=0;Ee<T.mipmaps.length;Ee++)q.__webglFramebuffer[be][Ee]=i.createFramebuffer()}else q.__webglFramebuffer[be]=i.createFramebuffer()}else{if(T.mipmaps&&T.mipmaps.length>0){q.__webglFramebuffer=[];for(let be=0;be<T.mipmaps.length;be++)q.__webglFramebuffer[be]=i.createFramebuffer()}else q.__webglFramebuffer=i.createFramebuffer();if(Le)for(let be=0,Ee=le.length;be<Ee;be++){let Je=n.get(le[be]);Je.__webglTexture===void 0&&(Je.__webglTexture=i.createTexture(),a.memory.textures++)}if(D.samples>0&&je(D)===!1){q.__webglMultisampledFramebuffer=i.createFramebuffer(),q.__webglColorRenderbuffer=[],t.bindFramebuffer(i.FRAMEBUFFER,q.__webglMultisampledFramebuffer);for(let be=0;be<le.length;be++){let Ee=le[be];q.__webglColorRenderbuffer[be]=i.createRenderbuffer(),i.bindRenderbuffer(i.RENDERBUFFER,q.__webglColorRenderbuffer[be]);let Je=s.convert(Ee.format,Ee.colorSpace),me=s.convert(Ee.type),Te=P(Ee.internalFormat,Je,me,Ee.colorSpace,D.isXRRenderTarget===!0),Ne=Ke(D);i.renderbufferStorageMultisample(i.RENDERBUFFER,Ne,Te,D.width,D.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+be,i.RENDERBUFFER,q.__webglColorRenderbuffer[be])}i.bindRenderbuffer(i.RENDERBUFFER,null),D.depthBuffer&&(q.__webglDepthRenderbuffer=i.createRenderbuffer(),W(q.__webglDepthRenderbuffer,D,!0)),t.bindFramebuffer(i.FRAMEBUFFER,null)}}if(se){t.bindTexture(i.TEXTURE_CUBE_MAP,oe.__webglTexture),ke(i.TEXTURE_CUBE_MAP,T);for(let be=0;be<6;be++)if(T.mipmaps&&T.mipmaps.length>0)for(let Ee=0;Ee<T.mipmaps.length;Ee++)te(q.__webglFramebuffer[be][Ee],D,T,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+be,Ee);else te(q.__webglFramebuffer[be],D,T,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+be,0);_(T)&&g(i.TEXTURE_CUBE_MAP),t.unbindTexture()}else if(Le){for(let be=0,Ee=le.length;be<Ee;be++){let Je=le[be],me=n.get(Je);t.bindTexture(i.TEXTURE_2D,me.__webglTexture),ke(i.TEXTURE_2D,Je),te(q.__webglFramebuffer,D,Je,i.COLOR_ATTACHMENT0+be,i.TEXTURE_2D,0),_(Je)&&g(i.TEXTURE_2D)}t.unbindTexture()}else{let be=i.TEXTURE_2D;if((D.isWebGL3DRenderTarget||D.isWebGLArrayRenderTarget)&&(be=D.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),t.bindTexture(be,oe.__webglTexture),ke(be,T),T.mipmaps&&T.mipmaps.length>0)for(let Ee=0;Ee<T.mipmaps.length;Ee++)te(q.__webglFramebuffer[Ee],D,T,i.COLOR_ATTACHMENT0,be,Ee);else te(q.__webglFramebuffer,D,T,i.COLOR_ATTACHMENT0,be,0);_(T)&&g(be),t.unbindTexture()}D.depthBuffer&&Oe(D)}function qe(D){let T=D.textures;for(let q=0,oe=T.length;q<oe;q++){let le=T[q];if(_(le)){let se=I(D),Le=n.get(le).__webglTexture;t.bindTexture(se,Le),g(se),t.unbindTexture()}}}let it=[],G=[];function Ut(D){if(D.samples>0){if(je(D)===!1){let T=D.textures,q=D.width,oe=D.height,le=i.COLOR_BUFFER_BIT,se=D.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,Le=n.get(D),be=T.length>1;if(be)for(let Ee=0;Ee<T.length;Ee++)t.bindFramebuffer(i.FRAMEBUFFER,Le.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+Ee,i.RENDERBUFFER,null),t.bindFramebuffer(i.FRAMEBUFFER,Le.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+Ee,i.TEXTURE_2D,null,0);t.bindFramebuffer(i.READ_FRAMEBUFFER,Le.__webglMultisampledFramebuffer),t.bindFramebuffer(i.DRAW_FRAMEBUFFER,Le.__webglFramebuffer);for(let Ee=0;Ee<T.length;Ee++){if(D.resolveDepthBuffer&&(D.depthBuffer&&(le|=i.DEPTH_BUFFER_BIT),D.stencilBuffer&&D.resolveStencilBuffer&&(le|=i.STENCIL_BUFFER_BIT)),be){i.framebufferRenderbuffer(i.READ_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.RENDERBUFFER,Le.__webglColorRenderbuffer[Ee]);let Je=n.get(T[Ee]).__webglTexture;i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,Je,0)}i.blitFramebuffer(0,0,q,oe,0,0,q,oe,le,i.NEAREST),l===!0&&(it.length=0,G.length=0,it.push(i.COLOR_ATTACHMENT0+Ee),D.depthBuffer&&D.resolveDepthBuffer===!1&&(it.push(se),G.push(se),i.invalidateFramebuffer(i.DRAW_FRAMEBUFFER,G)),i.invalidateFramebuffer(i.READ_FRAMEBUFFER,it))}if(t.bindFramebuffer(i.READ_FRAMEBUFFER,null),t.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),be)for(let Ee=0;Ee<T.length;Ee++){t.bindFramebuffer(i.FRAMEBUFFER,Le.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+Ee,i.RENDERBUFFER,Le.__webglColorRenderbuffer[Ee]);let Je=n.get(T[Ee]).__webglTexture;t.bindFramebuffer(i.FRAMEBUFFER,Le.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+Ee,i.TEXTURE_2D,Je,0)}t.bindFramebuffer(i.DRAW_FRAMEBUFFER,Le.__webglMultisampledFramebuffer)}else if(D.depthBuffer&&D.resolveDepthBuffer===!1&&l){let T=D.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;i.invalidateFramebuffer(i.DRAW_FRAMEBUFFER,[T])}}}function Ke(D){return Math.min(r.maxSamples,D.samples)}function je(D){let T=n.get(D);return D.samples>0&&e.has("WEBGL_multisampled_render_to_texture")===!0&&T.__useRenderToTexture!==!1}function Pe(D){let T=a.render.frame;d.get(D)!==T&&(d.set(D,T),D.update())}function ht(D,T){let q=D.colorSpace,oe=D.format,le=D.type;return D.isCompressedTexture===!0||D.isVideoTexture===!0||q!==ir&&q!==Yn&&(et.getTransfer(q)===ct?(oe!==sn||le!==Rn)&&console.warn("THREE.WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):console.error("THREE.WebGLTextures: Unsupported texture color space:",q)),T}function De(D){return typeof HTMLImageElement<"u"&&D instanceof HTMLImageElement?(h.width=D.naturalWidth||D.width,h.height=D.naturalHeight||D.height):typeof VideoFrame<"u"&&D instanceof VideoFrame?(h.width=D.displayWidth,h.height=D.displayHeight):(h.width=D.width,h.height=D.height),h}this.allocateTextureUnit=Z,this.resetTextureUnits=Q,this.setTexture2D=ie,this.setTexture2DArray=$,this.setTexture3D=ue,this.setTextureCube=j,this.rebindTextures=Xe,this.setupRenderTarget=ut,this.updateRenderTargetMipmap=qe,this.updateMultisampleRenderTarget=Ut,this.setupDepthRenderbuffer=Oe,this.setupFrameBufferTexture=te,this.useMultisampledRTT=je}function O_(i,e){function t(n,r=Yn){let s,a=et.getTransfer(r);if(n===Rn)return i.UNSIGNED_BYTE;if(n===dc)return i.UNSIGNED_SHORT_4_4_4_4;if(n===fc)return i.UNSIGNED_SHORT_5_5_5_1;if(n===Hh)return i.UNSIGNED_INT_5_9_9_9_REV;if(n===Gh)return i.BYTE;if(n===Vh)return i.SHORT;if(n===Ar)return i.UNSIGNED_SHORT;if(n===uc)return i.INT;if(n===mi)return i.UNSIGNED_INT;if(n===Tn)return i.FLOAT;if(n===Ir)return i.HALF_FLOAT;if(n===Wh)return i.ALPHA;if(n===Xh)return i.RGB;if(n===sn)return i.RGBA;if(n===qh)return i.LUMINANCE;if(n===Yh)return i.LUMINANCE_ALPHA;if(n===Xi)return i.DEPTH_COMPONENT;if(n===Ji)return i.DEPTH_STENCIL;if(n===Zh)return i.RED;if(n===pc)return i.RED_INTEGER;if(n===$h)return i.RG;if(n===mc)return i.RG_INTEGER;if(n===gc)return i.RGBA_INTEGER;if(n===_s||n===ys||n===xs||n===bs)if(a===ct)if(s=e.get("WEBGL_compressed_texture_s3tc_srgb"),s!==null){if(n===_s)return s.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(n===ys)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(n===xs)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(n===bs)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(s=e.get("WEBGL_compressed_texture_s3tc"),s!==null){if(n===_s)return s.COMPRESSED_RGB_S3TC_DXT1_EXT;if(n===ys)return s.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(n===xs)return s.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(n===bs)return s.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(n===co||n===lo||n===ho||n===uo)if(s=e.get("WEBGL_compressed_texture_pvrtc"),s!==null){if(n===co)return s.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(n===lo)return s.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(n===ho)return s.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(n===uo)return s.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(n===fo||n===po||n===mo)if(s=e.get("WEBGL_compressed_texture_etc"),s!==null){if(n===fo||n===po)return a===ct?s.COMPRESSED_SRGB8_ETC2:s.COMPRESSED_RGB8_ETC2;if(n===mo)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:s.COMPRESSED_RGBA8_ETC2_EAC}else return null;if(n===go||n===vo||n===_o||n===yo||n===xo||n===bo||n===So||n===Mo||n===wo||n===Eo||n===To||n===Ao||n===Co||n===Ro)if(s=e.get("WEBGL_compressed_texture_astc"),s!==null){if(n===go)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:s.COMPRESSED_RGBA_ASTC_4x4_KHR;if(n===vo)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:s.COMPRESSED_RGBA_ASTC_5x4_KHR;if(n===_o)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:s.COMPRESSED_RGBA_ASTC_5x5_KHR;if(n===yo)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:s.COMPRESSED_RGBA_ASTC_6x5_KHR;if(n===xo)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:s.COMPRESSED_RGBA_ASTC_6x6_KHR;if(n===bo)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:s.COMPRESSED_RGBA_ASTC_8x5_KHR;if(n===So)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:s.COMPRESSED_RGBA_ASTC_8x6_KHR;if(n===Mo)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:s.COMPRESSED_RGBA_ASTC_8x8_KHR;if(n===wo)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:s.COMPRESSED_RGBA_ASTC_10x5_KHR;if(n===Eo)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:s.COMPRESSED_RGBA_ASTC_10x6_KHR;if(n===To)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:s.COMPRESSED_RGBA_ASTC_10x8_KHR;if(n===Ao)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:s.COMPRESSED_RGBA_ASTC_10x10_KHR;if(n===Co)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:s.COMPRESSED_RGBA_ASTC_12x10_KHR;if(n===Ro)return a===ct?s.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:s.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(n===Ss||n===Po||n===Lo)if(s=e.get("EXT_texture_compression_bptc"),s!==null){if(n===Ss)return a===ct?s.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:s.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(n===Po)return s.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(n===Lo)return s.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(n===Kh||n===Io||n===Do||n===No)if(s=e.get("EXT_texture_compression_rgtc"),s!==null){if(n===Ss)return s.COMPRESSED_RED_RGTC1_EXT;if(n===Io)return s.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(n===Do)return s.COMPRESSED_RED_GREEN_RGTC2_EXT;if(n===No)return s.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return n===ji?i.UNSIGNED_INT_24_8:i[n]!==void 0?i[n]:null}return{convert:t}}var Ko=class extends Nt{constructor(e=[]){super(),this.isArrayCamera=!0,this.cameras=e}},Hi=class extends Kt{constructor(){super(),this.isGroup=!0,this.type="Group"}},k_={type:"move"},Tr=class{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new Hi,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new Hi,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new X,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new X),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new Hi,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new X,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new X),this._grip}dispatchEvent(e){return this._targetRay!==null&&this._targetRay.dispatchEvent(e),this._grip!==null&&this._grip.dispatchEvent(e),this._hand!==null&&this._hand.dispatchEvent(e),this}connect(e){if(e&&e.hand){let t=this._hand;if(t)for(let n of e.hand.values())this._getHandJoint(t,n)}return this.dispatchEvent({type:"connected",data:e}),this}disconnect(e){return this.dispatchEvent({type:"disconnected",data:e}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(e,t,n){let r=null,s=null,a=null,o=this._targetRay,l=this._grip,h=this._hand;if(e&&t.session.visibilityState!=="visible-blurred"){if(h&&e.hand){a=!0;for(let E of e.hand.values()){let _=t.getJointPose(E,n),g=this._getHandJoint(h,E);_!==null&&(g.matrix.fromArray(_.transform.matrix),g.matrix.decompose(g.position,g.rotation,g.scale),g.matrixWorldNeedsUpdate=!0,g.jointRadius=_.radius),g.visible=_!==null}let d=h.joints["index-finger-tip"],m=h.joints["thumb-tip"],f=d.position.distanceTo(m.position),v=.02,S=.005;h.inputState.pinching&&f>v+S?(h.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:e.handedness,target:this})):!h.inputState.pinching&&f<=v-S&&(h.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:e.handedness,target:this}))}else l!==null&&e.gripSpace&&(s=t.getPose(e.gripSpace,n),s!==null&&(l.matrix.fromArray(s.transform.matrix),l.matrix.decompose(l.position,l.rotation,l.scale),l.matrixWorldNeedsUpdate=!0,s.linearVelocity?(l.hasLinearVelocity=!0,l.linearVelocity.copy(s.linearVelocity)):l.hasLinearVelocity=!1,s.angularVelocity?(l.hasAngularVelocity=!0,l.angularVelocity.copy(s.angularVelocity)):l.hasAngularVelocity=!1));o!==null&&(r=t.getPose(e.targetRaySpace,n),r===null&&s!==null&&(r=s),r!==null&&(o.matrix.fromArray(r.transform.matrix),o.matrix.decompose(o.position,o.rotation,o.scale),o.matrixWorldNeedsUpdate=!0,r.linearVelocity?(o.hasLinearVelocity=!0,o.linearVelocity.copy(r.linearVelocity)):o.hasLinearVelocity=!1,r.angularVelocity?(o.hasAngularVelocity=!0,o.angularVelocity.copy(r.angularVelocity)):o.hasAngularVelocity=!1,this.dispatchEvent(k_)))}return o!==null&&(o.visible=r!==null),l!==null&&(l.visible=s!==null),h!==null&&(h.visible=a!==null),this}_getHandJoint(e,t){if(e.joints[t.jointName]===void 0){let n=new Hi;n.matrixAutoUpdate=!1,n.visible=!1,e.joints[t.jointName]=n,e.add(n)}return e.joints[t.jointName]}},B_=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,z_=`
uniform sampler2DArray depthColor;
uniform float depthWidth;
uniform float depthHeight;

void main() {

	vec2 coord = vec2( gl_FragCoord.x / depthWidth, gl_FragCoord.y / depthHeight );

	if ( coord.x >= 1.0 ) {

		gl_FragDepth = texture( depthColor, vec3( coord.x - 1.0, coord.y, 1 ) ).r;

	} else {

		gl_FragDepth = texture( depthColor, vec3( coord.x, coord.y, 0 ) ).r;

	}

}`,jo=class{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(e,t,n){if(this.texture===null){let r=new $t,s=e.properties.get(r);s.__webglTexture=t.texture,(t.depthNear!=n.depthNear||t.depthFar!=n.depthFar)&&(this.depthNear=t.depthNear,this.depthFar=t.depthFar),this.texture=r}}getMesh(e){if(this.texture!==null&&this.mesh===null){let t=e.cameras[0].viewport,n=new mn({vertexShader:B_,fragmentShader:z_,uniforms:{depthColor:{value:this.texture},depthWidth:{value:t.z},depthHeight:{value:t.w}}});this.mesh=new an(new Us(20,20),n)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}},Jo=class extends Pn{constructor(e,t){super();let n=this,r=null,s=1,a=null,o="local-floor",l=1,h=null,d=null,m=null,f=null,v=null,S=null,E=new jo,_=t.getContextAttributes(),g=null,I=null,P=[],C=[],H=new $e,U=null,N=new Nt;N.viewport=new gt;let V=new Nt;V.viewport=new gt;let L=[N,V],R=new Ko,F=null,Q=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(re){let de=P[re];return de===void 0&&(de=new Tr,P[re]=de),de.getTargetRaySpace()},this.getControllerGrip=function(re){let de=P[re];return de===void 0&&(de=new Tr,P[re]=de),de.getGripSpace()},this.getHand=function(re){let de=P[re];return de===void 0&&(de=new Tr,P[re]=de),de.getHandSpace()};function Z(re){let de=C.indexOf(re.inputSource);if(de===-1)return;let te=P[de];te!==void 0&&(te.update(re.inputSource,re.frame,h||a),te.dispatchEvent({type:re.type,data:re.inputSource}))}function J(){r.removeEventListener("select",Z),r.removeEventListener("selectstart",Z),r.removeEventListener("selectend",Z),r.removeEventListener("squeeze",Z),r.removeEventListener("squeezestart",Z),r.removeEventListener("squeezeend",Z),r.removeEventListener("end",J),r.removeEventListener("inputsourceschange",ie);for(let re=0;re<P.length;re++){let de=C[re];de!==null&&(C[re]=null,P[re].disconnect(de))}F=null,Q=null,E.reset(),e.setRenderTarget(g),v=null,f=null,m=null,r=null,I=null,We.stop(),n.isPresenting=!1,e.setPixelRatio(U),e.setSize(H.width,H.height,!1),n.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(re){s=re,n.isPresenting===!0&&console.warn("THREE.WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(re){o=re,n.isPresenting===!0&&console.warn("THREE.WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return h||a},this.setReferenceSpace=function(re){h=re},this.getBaseLayer=function(){return f!==null?f:v},this.getBinding=function(){return m},this.getFrame=function(){return S},this.getSession=function(){return r},this.setSession=async function(re){if(r=re,r!==null){if(g=e.getRenderTarget(),r.addEventListener("select",Z),r.addEventListener("selectstart",Z),r.addEventListener("selectend",Z),r.addEventListener("squeeze",Z),r.addEventListener("squeezestart",Z),r.addEventListener("squeezeend",Z),r.addEventListener("end",J),r.addEventListener("inputsourceschange",ie),_.xrCompatible!==!0&&await t.makeXRCompatible(),U=e.getPixelRatio(),e.getSize(H),r.renderState.layers===void 0){let de={antialias:_.antialias,alpha:!0,depth:_.depth,stencil:_.stencil,framebufferScaleFactor:s};v=new XRWebGLLayer(r,t,de),r.updateRenderState({baseLayer:v}),e.setPixelRatio(1),e.setSize(v.framebufferWidth,v.framebufferHeight,!1),I=new Ln(v.framebufferWidth,v.framebufferHeight,{format:sn,type:Rn,colorSpace:e.outputColorSpace,stencilBuffer:_.stencil})}else{let de=null,te=null,W=null;_.depth&&(W=_.stencil?t.DEPTH24_STENCIL8:t.DEPTH_COMPONENT24,de=_.stencil?Ji:Xi,te=_.stencil?ji:mi);let he={colorFormat:t.RGBA8,depthFormat:W,scaleFactor:s};m=new XRWebGLBinding(r,t),f=m.createProjectionLayer(he),r.updateRenderState({layers:[f]}),e.setPixelRatio(1),e.setSize(f.textureWidth,f.textureHeight,!1),I=new Ln(f.textureWidth,f.textureHeight,{format:sn,type:Rn,depthTexture:new Os(f.textureWidth,f.textureHeight,te,void 0,void 0,void 0,void 0,void 0,void 0,de),stencilBuffer:_.stencil,colorSpace:e.outputColorSpace,samples:_.antialias?4:0,resolveDepthBuffer:f.ignoreDepthValues===!1})}I.isXRRenderTarget=!0,this.setFoveation(l),h=null,a=await r.requestReferenceSpace(o),We.setContext(r),We.start(),n.isPresenting=!0,n.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(r!==null)return r.environmentBlendMode},this.getDepthTexture=function(){return E.getDepthTexture()};function ie(re){for(let de=0;de<re.removed.length;de++){let te=re.removed[de],W=C.indexOf(te);W>=0&&(C[W]=null,P[W].disconnect(te))}for(let de=0;de<re.added.length;de++){let te=re.added[de],W=C.indexOf(te);if(W===-1){for(let Oe=0;Oe<P.length;Oe++)if(Oe>=C.length){C.push(te),W=Oe;break}else if(C[Oe]===null){C[Oe]=te,W=Oe;break}if(W===-1)break}let he=P[W];he&&he.connect(te)}}let $=new X,ue=new X;function j(re,de,te){$.setFromMatrixPosition(de.matrixWorld),ue.setFromMatrixPosition(te.matrixWorld);let W=$.distanceTo(ue),he=de.projectionMatrix.elements,Oe=te.projectionMatrix.elements,Xe=he[14]/(he[10]-1),ut=he[14]/(he[10]+1),qe=(he[9]+1)/he[5],it=(he[9]-1)/he[5],G=(he[8]-1)/he[0],Ut=(Oe[8]+1)/Oe[0],Ke=Xe*G,je=Xe*Ut,Pe=W/(-G+Ut),ht=Pe*-G;if(de.matrixWorld.decompose(re.position,re.quaternion,re.scale),re.translateX(ht),re.translateZ(Pe),re.matrixWorld.compose(re.position,re.quaternion,re.scale),re.matrixWorldInverse.copy(re.matrixWorld).invert(),he[10]===-1)re.projectionMatrix.copy(de.projectionMatrix),re.projectionMatrixInverse.copy(de.projectionMatrixInverse);else{let De=Xe+Pe,D=ut+Pe,T=Ke-ht,q=je+(W-ht),oe=qe*ut/D*De,le=it*ut/D*De;re.projectionMatrix.makePerspective(T,q,oe,le,De,D),re.projectionMatrixInverse.copy(re.projectionMatrix).invert()}}function ge(re,de){de===null?re.matrixWorld.copy(re.matrix):re.matrixWorld.multiplyMatrices(de.matrixWorld,re.matrix),re.matrixWorldInverse.copy(re.matrixWorld).invert()}this.updateCamera=function(re){if(r===null)return;let de=re.near,te=re.far;E.texture!==null&&(E.depthNear>0&&(de=E.depthNear),E.depthFar>0&&(te=E.depthFar)),R.near=V.near=N.near=de,R.far=V.far=N.far=te,(F!==R.near||Q!==R.far)&&(r.updateRenderState({depthNear:R.near,depthFar:R.far}),F=R.near,Q=R.far),N.layers.mask=re.layers.mask|2,V.layers.mask=re.layers.mask|4,R.layers.mask=N.layers.mask|V.layers.mask;let W=re.parent,he=R.cameras;ge(R,W);for(let Oe=0;Oe<he.length;Oe++)ge(he[Oe],W);he.length===2?j(R,N,V):R.projectionMatrix.copy(N.projectionMatrix),_e(re,R,W)};function _e(re,de,te){te===null?re.matrix.copy(de.matrixWorld):(re.matrix.copy(te.matrixWorld),re.matrix.invert(),re.matrix.multiply(de.matrixWorld)),re.matrix.decompose(re.position,re.quaternion,re.scale),re.updateMatrixWorld(!0),re.projectionMatrix.copy(de.projectionMatrix),re.projectionMatrixInverse.copy(de.projectionMatrixInverse),re.isPerspectiveCamera&&(re.fov=Cr*2*Math.atan(1/re.projectionMatrix.elements[5]),re.zoom=1)}this.getCamera=function(){return R},this.getFoveation=function(){if(!(f===null&&v===null))return l},this.setFoveation=function(re){l=re,f!==null&&(f.fixedFoveation=re),v!==null&&v.fixedFoveation!==void 0&&(v.fixedFoveation=re)},this.hasDepthSensing=function(){return E.texture!==null},this.getDepthSensingMesh=function(){return E.getMesh(R)};let Ce=null;function ke(re,de){if(d=de.getViewerPose(h||a),S=de,d!==null){let te=d.views;v!==null&&(e.setRenderTargetFramebuffer(I,v.framebuffer),e.setRenderTarget(I));let W=!1;te.length!==R.cameras.length&&(R.cameras.length=0,W=!0);for(let Oe=0;Oe<te.length;Oe++){let Xe=te[Oe],ut=null;if(v!==null)ut=v.getViewport(Xe);else{let it=m.getViewSubImage(f,Xe);ut=it.viewport,Oe===0&&(e.setRenderTargetTextures(I,it.colorTexture,f.ignoreDepthValues?void 0:it.depthStencilTexture),e.setRenderTarget(I))}let qe=L[Oe];qe===void 0&&(qe=new Nt,qe.layers.enable(Oe),qe.viewport=new gt,L[Oe]=qe),qe.matrix.fromArray(Xe.transform.matrix),qe.matrix.decompose(qe.position,qe.quaternion,qe.scale),qe.projectionMatrix.fromArray(Xe.projectionMatrix),qe.projectionMatrixInverse.copy(qe.projectionMatrix).invert(),qe.viewport.set(ut.x,ut.y,ut.width,ut.height),Oe===0&&(R.matrix.copy(qe.matrix),R.matrix.decompose(R.position,R.quaternion,R.scale)),W===!0&&R.cameras.push(qe)}let he=r.enabledFeatures;if(he&&he.includes("depth-sensing")){let Oe=m.getDepthInformation(te[0]);Oe&&Oe.isValid&&Oe.texture&&E.init(e,Oe,r.renderState)}}for(let te=0;te<P.length;te++){let W=C[te],he=P[te];W!==null&&he!==void 0&&he.update(W,de,h||a)}Ce&&Ce(re,de),de.detectedPlanes&&n.dispatchEvent({type:"planesdetected",data:de}),S=null}let We=new nu;We.setAnimationLoop(ke),this.setAnimationLoop=function(re){Ce=re},this.dispose=function(){}}},ci=new Dn,G_=new _t;function V_(i,e){function t(_,g){_.matrixAutoUpdate===!0&&_.updateMatrix(),g.value.copy(_.matrix)}function n(_,g){g.color.getRGB(_.fogColor.value,tu(i)),g.isFog?(_.fogNear.value=g.near,_.fogFar.value=g.far):g.isFogExp2&&(_.fogDensity.value=g.density)}function r(_,g,I,P,C){g.isMeshBasicMaterial||g.isMeshLambertMaterial?s(_,g):g.isMeshToonMaterial?(s(_,g),m(_,g)):g.isMeshPhongMaterial?(s(_,g),d(_,g)):g.isMeshStandardMaterial?(s(_,g),f(_,g),g.isMeshPhysicalMaterial&&v(_,g,C)):g.isMeshMatcapMaterial?(s(_,g),S(_,g)):g.isMeshDepthMaterial?s(_,g):g.isMeshDistanceMaterial?(s(_,g),E(_,g)):g.isMeshNormalMaterial?s(_,g):g.isLineBasicMaterial?(a(_,g),g.isLineDashedMaterial&&o(_,g)):g.isPointsMaterial?l(_,g,I,P):g.isSpriteMaterial?h(_,g):g.isShadowMaterial?(_.color.value.copy(g.color),_.opacity.value=g.opacity):g.isShaderMaterial&&(g.uniformsNeedUpdate=!1)}function s(_,g){_.opacity.value=g.opacity,g.color&&_.diffuse.value.copy(g.color),g.emissive&&_.emissive.value.copy(g.emissive).multiplyScalar(g.emissiveIntensity),g.map&&(_.map.value=g.map,t(g.map,_.mapTransform)),g.alphaMap&&(_.alphaMap.value=g.alphaMap,t(g.alphaMap,_.alphaMapTransform)),g.bumpMap&&(_.bumpMap.value=g.bumpMap,t(g.bumpMap,_.bumpMapTransform),_.bumpScale.value=g.bumpScale,g.side===kt&&(_.bumpScale.value*=-1)),g.normalMap&&(_.normalMap.value=g.normalMap,t(g.normalMap,_.normalMapTransform),_.normalScale.value.copy(g.normalScale),g.side===kt&&_.normalScale.value.negate()),g.displacementMap&&(_.displacementMap.value=g.displacementMap,t(g.displacementMap,_.displacementMapTransform),_.displacementScale.value=g.displacementScale,_.displacementBias.value=g.displacementBias),g.emissiveMap&&(_.emissiveMap.value=g.emissiveMap,t(g.emissiveMap,_.emissiveMapTransform)),g.specularMap&&(_.specularMap.value=g.specularMap,t(g.specularMap,_.specularMapTransform)),g.alphaTest>0&&(_.alphaTest.value=g.alphaTest);let I=e.get(g),P=I.envMap,C=I.envMapRotation;P&&(_.envMap.value=P,ci.copy(C),ci.x*=-1,ci.y*=-1,ci.z*=-1,P.isCubeTexture&&P.isRenderTargetTexture===!1&&(ci.y*=-1,ci.z*=-1),_.envMapRotation.value.setFromMatrix4(G_.makeRotationFromEuler(ci)),_.flipEnvMap.value=P.isCubeTexture&&P.isRenderTargetTexture===!1?-1:1,_.reflectivity.value=g.reflectivity,_.ior.value=g.ior,_.refractionRatio.value=g.refractionRatio),g.lightMap&&(_.lightMap.value=g.lightMap,_.lightMapIntensity.value=g.lightMapIntensity,t(g.lightMap,_.lightMapTransform)),g.aoMap&&(_.aoMap.value=g.aoMap,_.aoMapIntensity.value=g.aoMapIntensity,t(g.aoMap,_.aoMapTransform))}function a(_,g){_.diffuse.value.copy(g.color),_.opacity.value=g.opacity,g.map&&(_.map.value=g.map,t(g.map,_.mapTransform))}function o(_,g){_.dashSize.value=g.dashSize,_.totalSize.value=g.dashSize+g.gapSize,_.scale.value=g.scale}function l(_,g,I,P){_.diffuse.value.copy(g.color),_.opacity.value=g.opacity,_.size.value=g.size*I,_.scale.value=P*.5,g.map&&(_.map.value=g.map,t(g.map,_.uvTransform)),g.alphaMap&&(_.alphaMap.value=g.alphaMap,t(g.alphaMap,_.alphaMapTransform)),g.alphaTest>0&&(_.alphaTest.value=g.alphaTest)}function h(_,g){_.diffuse.value.copy(g.color),_.opacity.value=g.opacity,_.rotation.value=g.rotation,g.map&&(_.map.value=g.map,t(g.map,_.mapTransform)),g.alphaMap&&(_.alphaMap.value=g.alphaMap,t(g.alphaMap,_.alphaMapTransform)),g.alphaTest>0&&(_.alphaTest.value=g.alphaTest)}function d(_,g){_.specular.value.copy(g.specular),_.shininess.value=Math.max(g.shininess,1e-4)}function m(_,g){g.gradientMap&&(_.gradientMap.value=g.gradientMap)}function f(_,g){_.metalness.value=g.metalness,g.metalnessMap&&(_.metalnessMap.value=g.metalnessMap,t(g.metalnessMap,_.metalnessMapTransform)),_.roughness.value=g.roughness,g.roughnessMap&&(_.roughnessMap.value=g.roughnessMap,t(g.roughnessMap,_.roughnessMapTransform)),g.envMap&&(_.envMapIntensity.value=g.envMapIntensity)}function v(_,g,I){_.ior.value=g.ior,g.sheen>0&&(_.sheenColor.value.copy(g.sheenColor).multiplyScalar(g.sheen),_.sheenRoughness.value=g.sheenRoughness,g.sheenColorMap&&(_.sheenColorMap.value=g.sheenColorMap,t(g.sheenColorMap,_.sheenColorMapTransform)),g.sheenRoughnessMap&&(_.sheenRoughnessMap.value=g.sheenRoughnessMap,t(g.sheenRoughnessMap,_.sheenRoughnessMapTransform))),g.clearcoat>0&&(_.clearcoat.value=g.clearcoat,_.clearcoatRoughness.value=g.clearcoatRoughness,g.clearcoatMap&&(_.clearcoatMap.value=g.clearcoatMap,t(g.clearcoatMap,_.clearcoatMapTransform)),g.clearcoatRoughnessMap&&(_.clearcoatRoughnessMap.value=g.clearcoatRoughnessMap,t(g.clearcoatRoughnessMap,_.clearcoatRoughnessMapTransform)),g.clearcoatNormalMap&&(_.clearcoatNormalMap.value=g.clearcoatNormalMap,t(g.clearcoatNormalMap,_.clearcoatNormalMapTransform),_.clearcoatNormalScale.value.copy(g.clearcoatNormalScale),g.side===kt&&_.clearcoatNormalScale.value.negate())),g.dispersion>0&&(_.dispersion.value=g.dispersion),g.iridescence>0&&(_.iridescence.value=g.iridescence,_.iridescenceIOR.value=g.iridescenceIOR,_.iridescenceThicknessMinimum.value=g.iridescenceThicknessRange[0],_.iridescenceThicknessMaximum.value=g.iridescenceThicknessRange[1],g.iridescenceMap&&(_.iridescenceMap.value=g.iridescenceMap,t(g.iridescenceMap,_.iridescenceMapTransform)),g.iridescenceThicknessMap&&(_.iridescenceThicknessMap.value=g.iridescenceThicknessMap,t(g.iridescenceThicknessMap,_.iridescenceThicknessMapTransform))),g.transmission>0&&(_.transmission.value=g.transmission,_.transmissionSamplerMap.value=I.texture,_.transmissionSamplerSize.value.set(I.width,I.height),g.transmissionMap&&(_.transmissionMap.value=g.transmissionMap,t(g.transmissionMap,_.transmissionMapTransform)),_.thickness.value=g.thickness,g.thicknessMap&&(_.thicknessMap.value=g.thicknessMap,t(g.thicknessMap,_.thicknessMapTransform)),_.attenuationDistance.value=g.attenuationDistance,_.attenuationColor.value.copy(g.attenuationColor)),g.anisotropy>0&&(_.anisotropyVector.value.set(g.anisotropy*Math.cos(g.anisotropyRotation),g.anisotropy*Math.sin(g.anisotropyRotation)),g.anisotropyMap&&(_.anisotropyMap.value=g.anisotropyMap,t(g.anisotropyMap,_.anisotropyMapTransform))),_.specularIntensity.value=g.specularIntensity,_.specularColor.value.copy(g.specularColor),g.specularColorMap&&(_.specularColorMap.value=g.specularColorMap,t(g.specularColorMap,_.specularColorMapTransform)),g.specularIntensityMap&&(_.specularIntensityMap.value=g.specularIntensityMap,t(g.specularIntensityMap,_.specularIntensityMapTransform))}function S(_,g){g.matcap&&(_.matcap.value=g.matcap)}function E(_,g){let I=e.get(g).light;_.referencePosition.value.setFromMatrixPosition(I.matrixWorld),_.nearDistance.value=I.shadow.camera.near,_.farDistance.value=I.shadow.camera.far}return{refreshFogUniforms:n,refreshMaterialUniforms:r}}function H_(i,e,t,n){let r={},s={},a=[],o=i.getParameter(i.MAX_UNIFORM_BUFFER_BINDINGS);function l(I,P){let C=P.program;n.uniformBlockBinding(I,C)}function h(I,P){let C=r[I.id];C===void 0&&(S(I),C=d(I),r[I.id]=C,I.addEventListener("dispose",_));let H=P.program;n.updateUBOMapping(I,H);let U=e.render.frame;s[I.id]!==U&&(f(I),s[I.id]=U)}function d(I){let P=m();I.__bindingPointIndex=P;let C=i.createBuffer(),H=I.__size,U=I.usage;return i.bindBuffer(i.UNIFORM_BUFFER,C),i.bufferData(i.UNIFORM_BUFFER,H,U),i.bindBuffer(i.UNIFORM_BUFFER,null),i.bindBufferBase(i.UNIFORM_BUFFER,P,C),C}function m(){for(let I=0;I<o;I++)if(a.indexOf(I)===-1)return a.push(I),I;return console.error("THREE.WebGLRenderer: Maximum number of simultaneously usable uniforms groups reached."),0}function f(I){let P=r[I.id],C=I.uniforms,H=I.__cache;i.bindBuffer(i.UNIFORM_BUFFER,P);for(let U=0,N=C.length;U<N;U++){let V=Array.isArray(C[U])?C[U]:[C[U]];for(let L=0,R=V.length;L<R;L++){let F=V[L];if(v(F,U,L,H)===!0){let Q=F.__offset,Z=Array.isArray(F.value)?F.value:[F.value],J=0;for(let ie=0;ie<Z.length;ie++){let $=Z[ie],ue=E($);typeof $=="number"||typeof $=="boolean"?(F.__data[0]=$,i.bufferSubData(i.UNIFORM_BUFFER,Q+J,F.__data)):$.isMatrix3?(F.__data[0]=$.elements[0],F.__data[1]=$.elements[1],F.__data[2]=$.elements[2],F.__data[3]=0,F.__data[4]=$.elements[3],F.__data[5]=$.elements[4],F.__data[6]=$.elements[5],F.__data[7]=0,F.__data[8]=$.elements[6],F.__data[9]=$.elements[7],F.__data[10]=$.elements[8],F.__data[11]=0):($.toArray(F.__data,J),J+=ue.storage/Float32Array.BYTES_PER_ELEMENT)}i.bufferSubData(i.UNIFORM_BUFFER,Q,F.__data)}}}i.bindBuffer(i.UNIFORM_BUFFER,null)}function v(I,P,C,H){let U=I.value,N=P+"_"+C;if(H[N]===void 0)return typeof U=="number"||typeof U=="boolean"?H[N]=U:H[N]=U.clone(),!0;{let V=H[N];if(typeof U=="number"||typeof U=="boolean"){if(V!==U)return H[N]=U,!0}else if(V.equals(U)===!1)return V.copy(U),!0}return!1}function S(I){let P=I.uniforms,C=0,H=16;for(let N=0,V=P.length;N<V;N++){let L=Array.isArray(P[N])?P[N]:[P[N]];for(let R=0,F=L.length;R<F;R++){let Q=L[R],Z=Array.isArray(Q.value)?Q.value:[Q.value];for(let J=0,ie=Z.length;J<ie;J++){let $=Z[J],ue=E($),j=C%H,ge=j%ue.boundary,_e=j+ge;C+=ge,_e!==0&&H-_e<ue.storage&&(C+=H-_e),Q.__data=new Float32Array(ue.storage/Float32Array.BYTES_PER_ELEMENT),Q.__offset=C,C+=ue.storage}}}let U=C%H;return U>0&&(C+=H-U),I.__size=C,I.__cache={},this}function E(I){let P={boundary:0,storage:0};return typeof I=="number"||typeof I=="boolean"?(P.boundary=4,P.storage=4):I.isVector2?(P.boundary=8,P.storage=8):I.isVector3||I.isColor?(P.boundary=16,P.storage=12):I.isVector4?(P.boundary=16,P.storage=16):I.isMatrix3?(P.boundary=48,P.storage=48):I.isMatrix4?(P.boundary=64,P.storage=64):I.isTexture?console.warn("THREE.WebGLRenderer: Texture samplers can not be part of an uniforms group."):console.warn("THREE.WebGLRenderer: Unsupported uniform value type.",I),P}function _(I){let P=I.target;P.removeEventListener("dispose",_);let C=a.indexOf(P.__bindingPointIndex);a.splice(C,1),i.deleteBuffer(r[P.id]),delete r[P.id],delete s[P.id]}function g(){for(let I in r)i.deleteBuffer(r[I]);a=[],r={},s={}}return{bind:l,update:h,dispose:g}}var ks=class{constructor(e={}){let{canvas:t=Yf(),context:n=null,depth:r=!0,stencil:s=!1,alpha:a=!1,antialias:o=!1,premultipliedAlpha:l=!0,preserveDrawingBuffer:h=!1,powerPreference:d="default",failIfMajorPerformanceCaveat:m=!1,reverseDepthBuffer:f=!1}=e;this.isWebGLRenderer=!0;let v;if(n!==null){if(typeof WebGLRenderingContext<"u"&&n instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");v=n.getContextAttributes().alpha}else v=a;let S=new Uint32Array(4),E=new Int32Array(4),_=null,g=null,I=[],P=[];this.domElement=t,this.debug={checkShaderErrors:!0,onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this._outputColorSpace=Yt,this.toneMapping=$n,this.toneMappingExposure=1;let C=this,H=!1,U=0,N=0,V=null,L=-1,R=null,F=new gt,Q=new gt,Z=null,J=new tt(0),ie=0,$=t.width,ue=t.height,j=1,ge=null,_e=null,Ce=new gt(0,0,$,ue),ke=new gt(0,0,$,ue),We=!1,re=new Ns,de=!1,te=!1,W=new _t,he=new _t,Oe=new X,Xe=new gt,ut={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0},qe=!1;function it(){return V===null?j:1}let G=n;function Ut(c,p){return t.getContext(c,p)}try{let c={alpha:!0,depth:r,stencil:s,antialias:o,premultipliedAlpha:l,preserveDrawingBuffer:h,powerPreference:d,failIfMajorPerformanceCaveat:m};if("setAttribute"in t&&t.setAttribute("data-engine",`three.js r${hc}`),t.addEventListener("webglcontextlost",ae,!1),t.addEventListener("webglcontextrestored",Me,!1),t.addEventListener("webglcontextcreationerror",Se,!1),G===null){let p="webgl2";if(G=Ut(p,c),G===null)throw Ut(p)?new Error("Error creating WebGL context with your selected attributes."):new Error("Error creating WebGL context.")}}catch(c){throw console.error("THREE.WebGLRenderer: "+c.message),c}let Ke,je,Pe,ht,De,D,T,q,oe,le,se,Le,be,Ee,Je,me,Te,Ne,Ue,Ae,Ze,Fe,rt,k;function xe(){Ke=new sv(G),Ke.init(),Fe=new O_(G,Ke),je=new Qg(G,Ke,e,Fe),Pe=new N_(G,Ke),je.reverseDepthBuffer&&f&&Pe.buffers.depth.setReversed(!0),ht=new cv(G),De=new b_,D=new F_(G,Ke,Pe,De,je,Fe,ht),T=new tv(C),q=new rv(C),oe=new mp(G),rt=new jg(G,oe),le=new av(G,oe,ht,rt),se=new hv(G,le,oe,ht),Ue=new lv(G,je,D),me=new ev(De),Le=new x_(C,T,q,Ke,je,rt,me),be=new V_(C,De),Ee=new M_,Je=new R_(Ke),Ne=new Kg(C,T,q,Pe,se,v,l),Te=new I_(C,se,je),k=new H_(G,ht,je,Pe),Ae=new Jg(G,Ke,ht),Ze=new ov(G,Ke,ht),ht.programs=Le.programs,C.capabilities=je,C.extensions=Ke,C.properties=De,C.renderLists=Ee,C.shadowMap=Te,C.state=Pe,C.info=ht}xe();let ee=new Jo(C,G);this.xr=ee,this.getContext=function(){return G},this.getContextAttributes=function(){return G.getContextAttributes()},this.forceContextLoss=function(){let c=Ke.get("WEBGL_lose_context");c&&c.loseContext()},this.forceContextRestore=function(){let c=Ke.get("WEBGL_lose_context");c&&c.restoreContext()},this.getPixelRatio=function(){return j},this.setPixelRatio=function(c){c!==void 0&&(j=c,this.setSize($,ue,!1))},this.getSize=function(c){return c.set($,ue)},this.setSize=function(c,p,y=!0){if(ee.isPresenting){console.warn("THREE.WebGLRenderer: Can't change size while VR device is presenting.");return}$=c,ue=p,t.width=Math.floor(c*j),t.height=Math.floor(p*j),y===!0&&(t.style.width=c+"px",t.style.height=p+"px"),this.setViewport(0,0,c,p)},this.getDrawingBufferSize=function(c){return c.set($*j,ue*j).floor()},this.setDrawingBufferSize=function(c,p,y){$=c,ue=p,j=y,t.width=Math.floor(c*y),t.height=Math.floor(p*y),this.setViewport(0,0,c,p)},this.getCurrentViewport=function(c){return c.copy(F)},this.getViewport=function(c){return c.copy(Ce)},this.setViewport=function(c,p,y,M){c.isVector4?Ce.set(c.x,c.y,c.z,c.w):Ce.set(c,p,y,M),Pe.viewport(F.copy(Ce).multiplyScalar(j).round())},this.getScissor=function(c){return c.copy(ke)},this.setScissor=function(c,p,y,M){c.isVector4?ke.set(c.x,c.y,c.z,c.w):ke.set(c,p,y,M),Pe.scissor(Q.copy(ke).multiplyScalar(j).round())},this.getScissorTest=function(){return We},this.setScissorTest=function(c){Pe.setScissorTest(We=c)},this.setOpaqueSort=function(c){ge=c},this.setTransparentSort=function(c){_e=c},this.getClearColor=function(c){return c.copy(Ne.getClearColor())},this.setClearColor=function(){Ne.setClearColor.apply(Ne,arguments)},this.getClearAlpha=function(){return Ne.getClearAlpha()},this.setClearAlpha=function(){Ne.setClearAlpha.apply(Ne,arguments)},this.clear=function(c=!0,p=!0,y=!0){let M=0;if(c){let A=!1;if(V!==null){let O=V.texture.format;A=O===gc||O===mc||O===pc}if(A){let O=V.texture.type,B=O===Rn||O===mi||O===Ar||O===ji||O===dc||O===fc,z=Ne.getClearColor(),K=Ne.getClearAlpha(),ne=z.r,fe=z.g,pe=z.b;B?(S[0]=ne,S[1]=fe,S[2]=pe,S[3]=K,G.clearBufferuiv(G.COLOR,0,S)):(E[0]=ne,E[1]=fe,E[2]=pe,E[3]=K,G.clearBufferiv(G.COLOR,0,E))}else M|=G.COLOR_BUFFER_BIT}p&&(M|=G.DEPTH_BUFFER_BIT),y&&(M|=G.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),G.clear(M)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.dispose=function(){t.removeEventListener("webglcontextlost",ae,!1),t.removeEventListener("webglcontextrestored",Me,!1),t.removeEventListener("webglcontextcreationerror",Se,!1),Ee.dispose(),Je.dispose(),De.dispose(),T.dispose(),q.dispose(),se.dispose(),rt.dispose(),k.dispose(),Le.dispose(),ee.dispose(),ee.removeEventListener("sessionstart",or),ee.removeEventListener("sessionend",Nr),Ft.stop()};function ae(c){c.preventDefault(),console.log("THREE.WebGLRenderer: Context Lost."),H=!0}function Me(){console.log("THREE.WebGLRenderer: Context Restored."),H=!1;let c=ht.autoReset,p=Te.enabled,y=Te.autoUpdate,M=Te.needsUpdate,A=Te.type;xe(),ht.autoReset=c,Te.enabled=p,Te.autoUpdate=y,Te.needsUpdate=M,Te.type=A}function Se(c){console.error("THREE.WebGLRenderer: A WebGL context could not be created. Reason: ",c.statusMessage)}function Be(c){let p=c.target;p.removeEventListener("dispose",Be),ft(p)}function ft(c){wt(c),De.remove(c)}function wt(c){let p=De.get(c).programs;p!==void 0&&(p.forEach(function(y){Le.releaseProgram(y)}),c.isShaderMaterial&&Le.releaseShaderCache(c))}this.renderBufferDirect=function(c,p,y,M,A,O){p===null&&(p=ut);let B=A.isMesh&&A.matrixWorld.determinant()<0,z=w(c,p,y,M,A);Pe.setMaterial(M,B);let K=y.index,ne=1;if(M.wireframe===!0){if(K=le.getWireframeAttribute(y),K===void 0)return;ne=2}let fe=y.drawRange,pe=y.attributes.position,Ie=fe.start*ne,ze=(fe.start+fe.count)*ne;O!==null&&(Ie=Math.max(Ie,O.start*ne),ze=Math.min(ze,(O.start+O.count)*ne)),K!==null?(Ie=Math.max(Ie,0),ze=Math.min(ze,K.count)):pe!=null&&(Ie=Math.max(Ie,0),ze=Math.min(ze,pe.count));let Ge=ze-Ie;if(Ge<0||Ge===1/0)return;rt.setup(A,M,z,y,K);let at,Ve=Ae;if(K!==null&&(at=oe.get(K),Ve=Ze,Ve.setIndex(at)),A.isMesh)M.wireframe===!0?(Pe.setLineWidth(M.wireframeLinewidth*it()),Ve.setMode(G.LINES)):Ve.setMode(G.TRIANGLES);else if(A.isLine){let we=M.linewidth;we===void 0&&(we=1),Pe.setLineWidth(we*it()),A.isLineSegments?Ve.setMode(G.LINES):A.isLineLoop?Ve.setMode(G.LINE_LOOP):Ve.setMode(G.LINE_STRIP)}else A.isPoints?Ve.setMode(G.POINTS):A.isSprite&&Ve.setMode(G.TRIANGLES);if(A.isBatchedMesh)if(A._multiDrawInstances!==null)Ve.renderMultiDrawInstances(A._multiDrawStarts,A._multiDrawCounts,A._multiDrawCount,A._multiDrawInstances);else if(Ke.get("WEBGL_multi_draw"))Ve.renderMultiDraw(A._multiDrawStarts,A._multiDrawCounts,A._multiDrawCount);else{let we=A._multiDrawStarts,mt=A._multiDrawCounts,Qe=A._multiDrawCount,Tt=K?oe.get(K).bytesPerElement:1,Qn=De.get(M).currentProgram.getUniforms();for(let Ot=0;Ot<Qe;Ot++)Qn.setValue(G,"_gl_DrawID",Ot),Ve.render(we[Ot]/Tt,mt[Ot])}else if(A.isInstancedMesh)Ve.renderInstances(Ie,Ge,A.count);else if(y.isInstancedBufferGeometry){let we=y._maxInstanceCount!==void 0?y._maxInstanceCount:1/0,mt=Math.min(y.instanceCount,we);Ve.renderInstances(Ie,Ge,mt)}else Ve.render(Ie,Ge)};function nt(c,p,y){c.transparent===!0&&c.side===En&&c.forceSinglePass===!1?(c.side=kt,c.needsUpdate=!0,Jn(c,p,y),c.side=Kn,c.needsUpdate=!0,Jn(c,p,y),c.side=En):Jn(c,p,y)}this.compile=function(c,p,y=null){y===null&&(y=c),g=Je.get(y),g.init(p),P.push(g),y.traverseVisible(function(A){A.isLight&&A.layers.test(p.layers)&&(g.pushLight(A),A.castShadow&&g.pushShadow(A))}),c!==y&&c.traverseVisible(function(A){A.isLight&&A.layers.test(p.layers)&&(g.pushLight(A),A.castShadow&&g.pushShadow(A))}),g.setupLights();let M=new Set;return c.traverse(function(A){if(!(A.isMesh||A.isPoints||A.isLine||A.isSprite))return;let O=A.material;if(O)if(Array.isArray(O))for(let B=0;B<O.length;B++){let z=O[B];nt(z,y,A),M.add(z)}else nt(O,y,A),M.add(O)}),P.pop(),g=null,M},this.compileAsync=function(c,p,y=null){let M=this.compile(c,p,y);return new Promise(A=>{function O(){if(M.forEach(function(B){De.get(B).currentProgram.isReady()&&M.delete(B)}),M.size===0){A(c);return}setTimeout(O,10)}Ke.get("KHR_parallel_shader_compile")!==null?O():setTimeout(O,10)})};let zt=null;function Ht(c){zt&&zt(c)}function or(){Ft.stop()}function Nr(){Ft.start()}let Ft=new nu;Ft.setAnimationLoop(Ht),typeof self<"u"&&Ft.setContext(self),this.setAnimationLoop=function(c){zt=c,ee.setAnimationLoop(c),c===null?Ft.stop():Ft.start()},ee.addEventListener("sessionstart",or),ee.addEventListener("sessionend",Nr),this.render=function(c,p){if(p!==void 0&&p.isCamera!==!0){console.error("THREE.WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(H===!0)return;if(c.matrixWorldAutoUpdate===!0&&c.updateMatrixWorld(),p.parent===null&&p.matrixWorldAutoUpdate===!0&&p.updateMatrixWorld(),ee.enabled===!0&&ee.isPresenting===!0&&(ee.cameraAutoUpdate===!0&&ee.updateCamera(p),p=ee.getCamera()),c.isScene===!0&&c.onBeforeRender(C,c,p,V),g=Je.get(c,P.length),g.init(p),P.push(g),he.multiplyMatrices(p.projectionMatrix,p.matrixWorldInverse),re.setFromProjectionMatrix(he),te=this.localClippingEnabled,de=me.init(this.clippingPlanes,te),_=Ee.get(c,I.length),_.init(),I.push(_),ee.enabled===!0&&ee.isPresenting===!0){let O=C.xr.getDepthSensingMesh();O!==null&&st(O,p,-1/0,C.sortObjects)}st(c,p,0,C.sortObjects),_.finish(),C.sortObjects===!0&&_.sort(ge,_e),qe=ee.enabled===!1||ee.isPresenting===!1||ee.hasDepthSensing()===!1,qe&&Ne.addToRenderList(_,c),this.info.render.frame++,de===!0&&me.beginShadows();let y=g.state.shadowsArray;Te.render(y,c,p),de===!0&&me.endShadows(),this.info.autoReset===!0&&this.info.reset();let M=_.opaque,A=_.transmissive;if(g.setupLights(),p.isArrayCamera){let O=p.cameras;if(A.length>0)for(let B=0,z=O.length;B<z;B++){let K=O[B];lr(M,A,c,K)}qe&&Ne.render(c);for(let B=0,z=O.length;B<z;B++){let K=O[B];cr(_,c,K,K.viewport)}}else A.length>0&&lr(M,A,c,p),qe&&Ne.render(c),cr(_,c,p);V!==null&&(D.updateMultisampleRenderTarget(V),D.updateRenderTargetMipmap(V)),c.isScene===!0&&c.onAfterRender(C,c,p),rt.resetDefaultState(),L=-1,R=null,P.pop(),P.length>0?(g=P[P.length-1],de===!0&&me.setGlobalState(C.clippingPlanes,g.state.camera)):g=null,I.pop(),I.length>0?_=I[I.length-1]:_=null};function st(c,p,y,M){if(c.visible===!1)return;if(c.layers.test(p.layers)){if(c.isGroup)y=c.renderOrder;else if(c.isLOD)c.autoUpdate===!0&&c.update(p);else if(c.isLight)g.pushLight(c),c.castShadow&&g.pushShadow(c);else if(c.isSprite){if(!c.frustumCulled||re.intersectsSprite(c)){M&&Xe.setFromMatrixPosition(c.matrixWorld).applyMatrix4(he);let B=se.update(c),z=c.material;z.visible&&_.push(c,B,z,y,Xe.z,null)}}else if((c.isMesh||c.isLine||c.isPoints)&&(!c.frustumCulled||re.intersectsObject(c))){let B=se.update(c),z=c.material;if(M&&(c.boundingSphere!==void 0?(c.boundingSphere===null&&c.computeBoundingSphere(),Xe.copy(c.boundingSphere.center)):(B.boundingSphere===null&&B.computeBoundingSphere(),Xe.copy(B.boundingSphere.center)),Xe.applyMatrix4(c.matrixWorld).applyMatrix4(he)),Array.isArray(z)){let K=B.groups;for(let ne=0,fe=K.length;ne<fe;ne++){let pe=K[ne],Ie=z[pe.materialIndex];Ie&&Ie.visible&&_.push(c,B,Ie,y,Xe.z,pe)}}else z.visible&&_.push(c,B,z,y,Xe.z,null)}}let O=c.children;for(let B=0,z=O.length;B<z;B++)st(O[B],p,y,M)}function cr(c,p,y,M){let A=c.opaque,O=c.transmissive,B=c.transparent;g.setupLightsView(y),de===!0&&me.setGlobalState(C.clippingPlanes,y),M&&Pe.viewport(F.copy(M)),A.length>0&&jn(A,p,y),O.length>0&&jn(O,p,y),B.length>0&&jn(B,p,y),Pe.buffers.depth.setTest(!0),Pe.buffers.depth.setMask(!0),Pe.buffers.color.setMask(!0),Pe.setPolygonOffset(!1)}function lr(c,p,y,M){if((y.isScene===!0?y.overrideMaterial:null)!==null)return;g.state.transmissionRenderTarget[M.id]===void 0&&(g.state.transmissionRenderTarget[M.id]=new Ln(1,1,{generateMipmaps:!0,type:Ke.has("EXT_color_buffer_half_float")||Ke.has("EXT_color_buffer_float")?Ir:Rn,minFilter:pi,samples:4,stencilBuffer:s,resolveDepthBuffer:!1,resolveStencilBuffer:!1,colorSpace:et.workingColorSpace}));let O=g.state.transmissionRenderTarget[M.id],B=M.viewport||F;O.setSize(B.z,B.w);let z=C.getRenderTarget();C.setRenderTarget(O),C.getClearColor(J),ie=C.getClearAlpha(),ie<1&&C.setClearColor(16777215,.5),C.clear(),qe&&Ne.render(y);let K=C.toneMapping;C.toneMapping=$n;let ne=M.viewport;if(M.viewport!==void 0&&(M.viewport=void 0),g.setupLightsView(M),de===!0&&me.setGlobalState(C.clippingPlanes,M),jn(c,y,M),D.updateMultisampleRenderTarget(O),D.updateRenderTargetMipmap(O),Ke.has("WEBGL_multisampled_render_to_texture")===!1){let fe=!1;for(let pe=0,Ie=p.length;pe<Ie;pe++){let ze=p[pe],Ge=ze.object,at=ze.geometry,Ve=ze.material,we=ze.group;if(Ve.side===En&&Ge.layers.test(M.layers)){let mt=Ve.side;Ve.side=kt,Ve.needsUpdate=!0,hr(Ge,y,M,at,Ve,we),Ve.side=mt,Ve.needsUpdate=!0,fe=!0}}fe===!0&&(D.updateMultisampleRenderTarget(O),D.updateRenderTargetMipmap(O))}C.setRenderTarget(z),C.setClearColor(J,ie),ne!==void 0&&(M.viewport=ne),C.toneMapping=K}function jn(c,p,y){let M=p.isScene===!0?p.overrideMaterial:null;for(let A=0,O=c.length;A<O;A++){let B=c[A],z=B.object,K=B.geometry,ne=M===null?B.material:M,fe=B.group;z.layers.test(y.layers)&&hr(z,p,y,K,ne,fe)}}function hr(c,p,y,M,A,O){c.onBeforeRender(C,p,y,M,A,O),c.modelViewMatrix.multiplyMatrices(y.matrixWorldInverse,c.matrixWorld),c.normalMatrix.getNormalMatrix(c.modelViewMatrix),A.onBeforeRender(C,p,y,M,c,O),A.transparent===!0&&A.side===En&&A.forceSinglePass===!1?(A.side=kt,A.needsUpdate=!0,C.renderBufferDirect(y,p,M,A,c,O),A.side=Kn,A.needsUpdate=!0,C.renderBufferDirect(y,p,M,A,c,O),A.side=En):C.renderBufferDirect(y,p,M,A,c,O),c.onAfterRender(C,p,y,M,A,O)}function Jn(c,p,y){p.isScene!==!0&&(p=ut);let M=De.get(c),A=g.state.lights,O=g.state.shadowsArray,B=A.state.version,z=Le.getParameters(c,A.state,O,p,y),K=Le.getProgramCacheKey(z),ne=M.programs;M.environment=c.isMeshStandardMaterial?p.environment:null,M.fog=p.fog,M.envMap=(c.isMeshStandardMaterial?q:T).get(c.envMap||M.environment),M.envMapRotation=M.environment!==null&&c.envMap===null?p.environmentRotation:c.envMapRotation,ne===void 0&&(c.addEventListener("dispose",Be),ne=new Map,M.programs=ne);let fe=ne.get(K);if(fe!==void 0){if(M.currentProgram===fe&&M.lightsStateVersion===B)return x(c,z),fe}else z.uniforms=Le.getUniforms(c),c.onBeforeCompile(z,C),fe=Le.acquireProgram(z,K),ne.set(K,fe),M.uniforms=z.uniforms;let pe=M.uniforms;return(!c.isShaderMaterial&&!c.isRawShaderMaterial||c.clipping===!0)&&(pe.clippingPlanes=me.uniform),x(c,z),M.needsLights=u(c),M.lightsStateVersion=B,M.needsLights&&(pe.ambientLightColor.value=A.state.ambient,pe.lightProbe.value=A.state.probe,pe.directionalLights.value=A.state.directional,pe.directionalLightShadows.value=A.state.directionalShadow,pe.spotLights.value=A.state.spot,pe.spotLightShadows.value=A.state.spotShadow,pe.rectAreaLights.value=A.state.rectArea,pe.ltc_1.value=A.state.rectAreaLTC1,pe.ltc_2.value=A.state.rectAreaLTC2,pe.pointLights.value=A.state.point,pe.pointLightShadows.value=A.state.pointShadow,pe.hemisphereLights.value=A.state.hemi,pe.directionalShadowMap.value=A.state.directionalShadowMap,pe.directionalShadowMatrix.value=A.state.directionalShadowMatrix,pe.spotShadowMap.value=A.state.spotShadowMap,pe.spotLightMatrix.value=A.state.spotLightMatrix,pe.spotLightMap.value=A.state.spotLightMap,pe.pointShadowMap.value=A.state.pointShadowMap,pe.pointShadowMatrix.value=A.state.pointShadowMatrix),M.currentProgram=fe,M.uniformsList=null,fe}function gn(c){if(c.uniformsList===null){let p=c.currentProgram.getUniforms();c.uniformsList=Yi.seqWithValue(p.seq,c.uniforms)}return c.uniformsList}function x(c,p){let y=De.get(c);y.outputColorSpace=p.outputColorSpace,y.batching=p.batching,y.batchingColor=p.batchingColor,y.instancing=p.instancing,y.instancingColor=p.instancingColor,y.instancingMorph=p.instancingMorph,y.skinning=p.skinning,y.morphTargets=p.morphTargets,y.morphNormals=p.morphNormals,y.morphColors=p.morphColors,y.morphTargetsCount=p.morphTargetsCount,y.numClippingPlanes=p.numClippingPlanes,y.numIntersection=p.numClipIntersection,y.vertexAlphas=p.vertexAlphas,y.vertexTangents=p.vertexTangents,y.toneMapping=p.toneMapping}function w(c,p,y,M,A){p.isScene!==!0&&(p=ut),D.resetTextureUnits();let O=p.fog,B=M.isMeshStandardMaterial?p.environment:null,z=V===null?C.outputColorSpace:V.isXRRenderTarget===!0?V.texture.colorSpace:ir,K=(M.isMeshStandardMaterial?q:T).get(M.envMap||B),ne=M.vertexColors===!0&&!!y.attributes.color&&y.attributes.color.itemSize===4,fe=!!y.attributes.tangent&&(!!M.normalMap||M.anisotropy>0),pe=!!y.morphAttributes.position,Ie=!!y.morphAttributes.normal,ze=!!y.morphAttributes.color,Ge=$n;M.toneMapped&&(V===null||V.isXRRenderTarget===!0)&&(Ge=C.toneMapping);let at=y.morphAttributes.position||y.morphAttributes.normal||y.morphAttributes.color,Ve=at!==void 0?at.length:0,we=De.get(M),mt=g.state.lights;if(de===!0&&(te===!0||c!==R)){let Wt=c===R&&M.id===L;me.setState(M,c,Wt)}let Qe=!1;M.version===we.__version?(we.needsLights&&we.lightsStateVersion!==mt.state.version||we.outputColorSpace!==z||A.isBatchedMesh&&we.batching===!1||!A.isBatchedMesh&&we.batching===!0||A.isBatchedMesh&&we.batchingColor===!0&&A.colorTexture===null||A.isBatchedMesh&&we.batchingColor===!1&&A.colorTexture!==null||A.isInstancedMesh&&we.instancing===!1||!A.isInstancedMesh&&we.instancing===!0||A.isSkinnedMesh&&we.skinning===!1||!A.isSkinnedMesh&&we.skinning===!0||A.isInstancedMesh&&we.instancingColor===!0&&A.instanceColor===null||A.isInstancedMesh&&we.instancingColor===!1&&A.instanceColor!==null||A.isInstancedMesh&&we.instancingMorph===!0&&A.morphTexture===null||A.isInstancedMesh&&we.instancingMorph===!1&&A.morphTexture!==null||we.envMap!==K||M.fog===!0&&we.fog!==O||we.numClippingPlanes!==void 0&&(we.numClippingPlanes!==me.numPlanes||we.numIntersection!==me.numIntersection)||we.vertexAlphas!==ne||we.vertexTangents!==fe||we.morphTargets!==pe||we.morphNormals!==Ie||we.morphColors!==ze||we.toneMapping!==Ge||we.morphTargetsCount!==Ve)&&(Qe=!0):(Qe=!0,we.__version=M.version);let Tt=we.currentProgram;Qe===!0&&(Tt=Jn(M,p,A));let Qn=!1,Ot=!1,Fn=!1,dt=Tt.getUniforms(),un=we.uniforms;if(Pe.useProgram(Tt.program)&&(Qn=!0,Ot=!0,Fn=!0),M.id!==L&&(L=M.id,Ot=!0),Qn||R!==c){Pe.buffers.depth.getReversed()?(W.copy(c.projectionMatrix),$f(W),Kf(W),dt.setValue(G,"projectionMatrix",W)):dt.setValue(G,"projectionMatrix",c.projectionMatrix),dt.setValue(G,"viewMatrix",c.matrixWorldInverse);let On=dt.map.cameraPosition;On!==void 0&&On.setValue(G,Oe.setFromMatrixPosition(c.matrixWorld)),je.logarithmicDepthBuffer&&dt.setValue(G,"logDepthBufFC",2/(Math.log(c.far+1)/Math.LN2)),(M.isMeshPhongMaterial||M.isMeshToonMaterial||M.isMeshLambertMaterial||M.isMeshBasicMaterial||M.isMeshStandardMaterial||M.isShaderMaterial)&&dt.setValue(G,"isOrthographic",c.isOrthographicCamera===!0),R!==c&&(R=c,Ot=!0,Fn=!0)}if(A.isSkinnedMesh){dt.setOptional(G,A,"bindMatrix"),dt.setOptional(G,A,"bindMatrixInverse");let Wt=A.skeleton;Wt&&(Wt.boneTexture===null&&Wt.computeBoneTexture(),dt.setValue(G,"boneTexture",Wt.boneTexture,D))}A.isBatchedMesh&&(dt.setOptional(G,A,"batchingTexture"),dt.setValue(G,"batchingTexture",A._matricesTexture,D),dt.setOptional(G,A,"batchingIdTexture"),dt.setValue(G,"batchingIdTexture",A._indirectTexture,D),dt.setOptional(G,A,"batchingColorTexture"),A._colorsTexture!==null&&dt.setValue(G,"batchingColorTexture",A._colorsTexture,D));let ur=y.morphAttributes;if((ur.position!==void 0||ur.normal!==void 0||ur.color!==void 0)&&Ue.update(A,y,Tt),(Ot||we.receiveShadow!==A.receiveShadow)&&(we.receiveShadow=A.receiveShadow,dt.setValue(G,"receiveShadow",A.receiveShadow)),M.isMeshGouraudMaterial&&M.envMap!==null&&(un.envMap.value=K,un.flipEnvMap.value=K.isCubeTexture&&K.isRenderTargetTexture===!1?-1:1),M.isMeshStandardMaterial&&M.envMap===null&&p.environment!==null&&(un.envMapIntensity.value=p.environmentIntensity),Ot&&(dt.setValue(G,"toneMappingExposure",C.toneMappingExposure),we.needsLights&&b(un,Fn),O&&M.fog===!0&&be.refreshFogUniforms(un,O),be.refreshMaterialUniforms(un,M,j,ue,g.state.transmissionRenderTarget[c.id]),Yi.upload(G,gn(we),un,D)),M.isShaderMaterial&&M.uniformsNeedUpdate===!0&&(Yi.upload(G,gn(we),un,D),M.uniformsNeedUpdate=!1),M.isSpriteMaterial&&dt.setValue(G,"center",A.center),dt.setValue(G,"modelViewMatrix",A.modelViewMatrix),dt.setValue(G,"normalMatrix",A.normalMatrix),dt.setValue(G,"modelMatrix",A.matrixWorld),M.isShaderMaterial||M.isRawShaderMaterial){let Wt=M.uniformsGroups;for(let On=0,kn=Wt.length;On<kn;On++){let Rc=Wt[On];k.update(Rc,Tt),k.bind(Rc,Tt)}}return Tt}function b(c,p){c.ambientLightColor.needsUpdate=p,c.lightProbe.needsUpdate=p,c.directionalLights.needsUpdate=p,c.directionalLightShadows.needsUpdate=p,c.pointLights.needsUpdate=p,c.pointLightShadows.needsUpdate=p,c.spotLights.needsUpdate=p,c.spotLightShadows.needsUpdate=p,c.rectAreaLights.needsUpdate=p,c.hemisphereLights.needsUpdate=p}function u(c){return c.isMeshLambertMaterial||c.isMeshToonMaterial||c.isMeshPhongMaterial||c.isMeshStandardMaterial||c.isShadowMaterial||c.isShaderMaterial&&c.lights===!0}this.getActiveCubeFace=function(){return U},this.getActiveMipmapLevel=function(){return N},this.getRenderTarget=function(){return V},this.setRenderTargetTextures=function(c,p,y){De.get(c.texture).__webglTexture=p,De.get(c.depthTexture).__webglTexture=y;let M=De.get(c);M.__hasExternalTextures=!0,M.__autoAllocateDepthBuffer=y===void 0,M.__autoAllocateDepthBuffer||Ke.has("WEBGL_multisampled_render_to_texture")===!0&&(console.warn("THREE.WebGLRenderer: Render-to-texture extension was disabled because an external texture was provided"),M.__useRenderToTexture=!1)},this.setRenderTargetFramebuffer=function(c,p){let y=De.get(c);y.__webglFramebuffer=p,y.__useDefaultFramebuffer=p===void 0},this.setRenderTarget=function(c,p=0,y=0){V=c,U=p,N=y;let M=!0,A=null,O=!1,B=!1;if(c){let K=De.get(c);if(K.__useDefaultFramebuffer!==void 0)Pe.bindFramebuffer(G.FRAMEBUFFER,null),M=!1;else if(K.__webglFramebuffer===void 0)D.setupRenderTarget(c);else if(K.__hasExternalTextures)D.rebindTextures(c,De.get(c.texture).__webglTexture,De.get(c.depthTexture).__webglTexture);else if(c.depthBuffer){let pe=c.depthTexture;if(K.__boundDepthTexture!==pe){if(pe!==null&&De.has(pe)&&(c.width!==pe.image.width||c.height!==pe.image.height))throw new Error("WebGLRenderTarget: Attached DepthTexture is initialized to the incorrect size.");D.setupDepthRenderbuffer(c)}}let ne=c.texture;(ne.isData3DTexture||ne.isDataArrayTexture||ne.isCompressedArrayTexture)&&(B=!0);let fe=De.get(c).__webglFramebuffer;c.isWebGLCubeRenderTarget?(Array.isArray(fe[p])?A=fe[p][y]:A=fe[p],O=!0):c.samples>0&&D.useMultisampledRTT(c)===!1?A=De.get(c).__webglMultisampledFramebuffer:Array.isArray(fe)?A=fe[y]:A=fe,F.copy(c.viewport),Q.copy(c.scissor),Z=c.scissorTest}else F.copy(Ce).multiplyScalar(j).floor(),Q.copy(ke).multiplyScalar(j).floor(),Z=We;if(Pe.bindFramebuffer(G.FRAMEBUFFER,A)&&M&&Pe.drawBuffers(c,A),Pe.viewport(F),Pe.scissor(Q),Pe.setScissorTest(Z),O){let K=De.get(c.texture);G.framebufferTexture2D(G.FRAMEBUFFER,G.COLOR_ATTACHMENT0,G.TEXTURE_CUBE_MAP_POSITIVE_X+p,K.__webglTexture,y)}else if(B){let K=De.get(c.texture),ne=p||0;G.framebufferTextureLayer(G.FRAMEBUFFER,G.COLOR_ATTACHMENT0,K.__webglTexture,y||0,ne)}L=-1},this.readRenderTargetPixels=function(c,p,y,M,A,O,B){if(!(c&&c.isWebGLRenderTarget)){console.error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let z=De.get(c).__webglFramebuffer;if(c.isWebGLCubeRenderTarget&&B!==void 0&&(z=z[B]),z){Pe.bindFramebuffer(G.FRAMEBUFFER,z);try{let K=c.texture,ne=K.format,fe=K.type;if(!je.textureFormatReadable(ne)){console.error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(!je.textureTypeReadable(fe)){console.error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}p>=0&&p<=c.width-M&&y>=0&&y<=c.height-A&&G.readPixels(p,y,M,A,Fe.convert(ne),Fe.convert(fe),O)}finally{let K=V!==null?De.get(V).__webglFramebuffer:null;Pe.bindFramebuffer(G.FRAMEBUFFER,K)}}},this.readRenderTargetPixelsAsync=async function(c,p,y,M,A,O,B){if(!(c&&c.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let z=De.get(c).__webglFramebuffer;if(c.isWebGLCubeRenderTarget&&B!==void 0&&(z=z[B]),z){let K=c.texture,ne=K.format,fe=K.type;if(!je.textureFormatReadable(ne))throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(!je.textureTypeReadable(fe))throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");if(p>=0&&p<=c.width-M&&y>=0&&y<=c.height-A){Pe.bindFramebuffer(G.FRAMEBUFFER,z);let pe=G.createBuffer();G.bindBuffer(G.PIXEL_PACK_BUFFER,pe),G.bufferData(G.PIXEL_PACK_BUFFER,O.byteLength,G.STREAM_READ),G.readPixels(p,y,M,A,Fe.convert(ne),Fe.convert(fe),0);let Ie=V!==null?De.get(V).__webglFramebuffer:null;Pe.bindFramebuffer(G.FRAMEBUFFER,Ie);let ze=G.fenceSync(G.SYNC_GPU_COMMANDS_COMPLETE,0);return G.flush(),await Zf(G,ze,4),G.bindBuffer(G.PIXEL_PACK_BUFFER,pe),G.getBufferSubData(G.PIXEL_PACK_BUFFER,0,O),G.deleteBuffer(pe),G.deleteSync(ze),O}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")}},this.copyFramebufferToTexture=function(c,p=null,y=0){c.isTexture!==!0&&(Sr("WebGLRenderer: copyFramebufferToTexture function signature has changed."),p=arguments[0]||null,c=arguments[1]);let M=Math.pow(2,-y),A=Math.floor(c.image.width*M),O=Math.floor(c.image.height*M),B=p!==null?p.x:0,z=p!==null?p.y:0;D.setTexture2D(c,0),G.copyTexSubImage2D(G.TEXTURE_2D,y,0,0,B,z,A,O),Pe.unbindTexture()},this.copyTextureToTexture=function(c,p,y=null,M=null,A=0){c.isTexture!==!0&&(Sr("WebGLRenderer: copyTextureToTexture function signature has changed."),M=arguments[0]||null,c=arguments[1],p=arguments[2],A=arguments[3]||0,y=null);let O,B,z,K,ne,fe,pe,Ie,ze,Ge=c.isCompressedTexture?c.mipmaps[A]:c.image;y!==null?(O=y.max.x-y.min.x,B=y.max.y-y.min.y,z=y.isBox3?y.max.z-y.min.z:1,K=y.min.x,ne=y.min.y,fe=y.isBox3?y.min.z:0):(O=Ge.width,B=Ge.height,z=Ge.depth||1,K=0,ne=0,fe=0),M!==null?(pe=M.x,Ie=M.y,ze=M.z):(pe=0,Ie=0,ze=0);let at=Fe.convert(p.format),Ve=Fe.convert(p.type),we;p.isData3DTexture?(D.setTexture3D(p,0),we=G.TEXTURE_3D):p.isDataArrayTexture||p.isCompressedArrayTexture?(D.setTexture2DArray(p,0),we=G.TEXTURE_2D_ARRAY):(D.setTexture2D(p,0),we=G.TEXTURE_2D),G.pixelStorei(G.UNPACK_FLIP_Y_WEBGL,p.flipY),G.pixelStorei(G.UNPACK_PREMULTIPLY_ALPHA_WEBGL,p.premultiplyAlpha),G.pixelStorei(G.UNPACK_ALIGNMENT,p.unpackAlignment);let mt=G.getParameter(G.UNPACK_ROW_LENGTH),Qe=G.getParameter(G.UNPACK_IMAGE_HEIGHT),Tt=G.getParameter(G.UNPACK_SKIP_PIXELS),Qn=G.getParameter(G.UNPACK_SKIP_ROWS),Ot=G.getParameter(G.UNPACK_SKIP_IMAGES);G.pixelStorei(G.UNPACK_ROW_LENGTH,Ge.width),G.pixelStorei(G.UNPACK_IMAGE_HEIGHT,Ge.height),G.pixelStorei(G.UNPACK_SKIP_PIXELS,K),G.pixelStorei(G.UNPACK_SKIP_ROWS,ne),G.pixelStorei(G.UNPACK_SKIP_IMAGES,fe);let Fn=c.isDataArrayTexture||c.isData3DTexture,dt=p.isDataArrayTexture||p.isData3DTexture;if(c.isRenderTargetTexture||c.isDepthTexture){let un=De.get(c),ur=De.get(p),Wt=De.get(un.__renderTarget),On=De.get(ur.__renderTarget);Pe.bindFramebuffer(G.READ_FRAMEBUFFER,Wt.__webglFramebuffer),Pe.bindFramebuffer(G.DRAW_FRAMEBUFFER,On.__webglFramebuffer);for(let kn=0;kn<z;kn++)Fn&&G.framebufferTextureLayer(G.READ_FRAMEBUFFER,G.COLOR_ATTACHMENT0,De.get(c).__webglTexture,A,fe+kn),c.isDepthTexture?(dt&&G.framebufferTextureLayer(G.DRAW_FRAMEBUFFER,G.COLOR_ATTACHMENT0,De.get(p).__webglTexture,A,ze+kn),G.blitFramebuffer(K,ne,O,B,pe,Ie,O,B,G.DEPTH_BUFFER_BIT,G.NEAREST)):dt?G.copyTexSubImage3D(we,A,pe,Ie,ze+kn,K,ne,O,B):G.copyTexSubImage2D(we,A,pe,Ie,ze+kn,K,ne,O,B);Pe.bindFramebuffer(G.READ_FRAMEBUFFER,null),Pe.bindFramebuffer(G.DRAW_FRAMEBUFFER,null)}else dt?c.isDataTexture||c.isData3DTexture?G.texSubImage3D(we,A,pe,Ie,ze,O,B,z,at,Ve,Ge.data):p.isCompressedArrayTexture?G.compressedTexSubImage3D(we,A,pe,Ie,ze,O,B,z,at,Ge.data):G.texSubImage3D(we,A,pe,Ie,ze,O,B,z,at,Ve,Ge):c.isDataTexture?G.texSubImage2D(G.TEXTURE_2D,A,pe,Ie,O,B,at,Ve,Ge.data):c.isCompressedTexture?G.compressedTexSubImage2D(G.TEXTURE_2D,A,pe,Ie,Ge.width,Ge.height,at,Ge.data):G.texSubImage2D(G.TEXTURE_2D,A,pe,Ie,O,B,at,Ve,Ge);G.pixelStorei(G.UNPACK_ROW_LENGTH,mt),G.pixelStorei(G.UNPACK_IMAGE_HEIGHT,Qe),G.pixelStorei(G.UNPACK_SKIP_PIXELS,Tt),G.pixelStorei(G.UNPACK_SKIP_ROWS,Qn),G.pixelStorei(G.UNPACK_SKIP_IMAGES,Ot),A===0&&p.generateMipmaps&&G.generateMipmap(we),Pe.unbindTexture()},this.copyTextureToTexture3D=function(c,p,y=null,M=null,A=0){return c.isTexture!==!0&&(Sr("WebGLRenderer: copyTextureToTexture3D function signature has changed."),y=arguments[0]||null,M=arguments[1]||null,c=arguments[2],p=arguments[3],A=arguments[4]||0),Sr('WebGLRenderer: copyTextureToTexture3D function has been deprecated. Use "copyTextureToTexture" instead.'),this.copyTextureToTexture(c,p,y,M,A)},this.initRenderTarget=function(c){De.get(c).__webglFramebuffer===void 0&&D.setupRenderTarget(c)},this.initTexture=function(c){c.isCubeTexture?D.setTextureCube(c,0):c.isData3DTexture?D.setTexture3D(c,0):c.isDataArrayTexture||c.isCompressedArrayTexture?D.setTexture2DArray(c,0):D.setTexture2D(c,0),Pe.unbindTexture()},this.resetState=function(){U=0,N=0,V=null,Pe.reset(),rt.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return An}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(e){this._outputColorSpace=e;let t=this.getContext();t.drawingBufferColorspace=et._getDrawingBufferColorSpace(e),t.unpackColorSpace=et._getUnpackColorSpace()}};var Bs=class extends Kt{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new Dn,this.environmentIntensity=1,this.environmentRotation=new Dn,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(e,t){return super.copy(e,t),e.background!==null&&(this.background=e.background.clone()),e.environment!==null&&(this.environment=e.environment.clone()),e.fog!==null&&(this.fog=e.fog.clone()),this.backgroundBlurriness=e.backgroundBlurriness,this.backgroundIntensity=e.backgroundIntensity,this.backgroundRotation.copy(e.backgroundRotation),this.environmentIntensity=e.environmentIntensity,this.environmentRotation.copy(e.environmentRotation),e.overrideMaterial!==null&&(this.overrideMaterial=e.overrideMaterial.clone()),this.matrixAutoUpdate=e.matrixAutoUpdate,this}toJSON(e){let t=super.toJSON(e);return this.fog!==null&&(t.object.fog=this.fog.toJSON()),this.backgroundBlurriness>0&&(t.object.backgroundBlurriness=this.backgroundBlurriness),this.backgroundIntensity!==1&&(t.object.backgroundIntensity=this.backgroundIntensity),t.object.backgroundRotation=this.backgroundRotation.toArray(),this.environmentIntensity!==1&&(t.object.environmentIntensity=this.environmentIntensity),t.object.environmentRotation=this.environmentRotation.toArray(),t}};var Pr=class extends gi{static get type(){return"PointsMaterial"}constructor(e){super(),this.isPointsMaterial=!0,this.color=new tt(16777215),this.map=null,this.alphaMap=null,this.size=1,this.sizeAttenuation=!0,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.alphaMap=e.alphaMap,this.size=e.size,this.sizeAttenuation=e.sizeAttenuation,this.fog=e.fog,this}},Fh=new _t,Qo=new er,ms=new Qi,gs=new X,zs=class extends Kt{constructor(e=new pn,t=new Pr){super(),this.isPoints=!0,this.type="Points",this.geometry=e,this.material=t,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}raycast(e,t){let n=this.geometry,r=this.matrixWorld,s=e.params.Points.threshold,a=n.drawRange;if(n.boundingSphere===null&&n.computeBoundingSphere(),ms.copy(n.boundingSphere),ms.applyMatrix4(r),ms.radius+=s,e.ray.intersectsSphere(ms)===!1)return;Fh.copy(r).invert(),Qo.copy(e.ray).applyMatrix4(Fh);let o=s/((this.scale.x+this.scale.y+this.scale.z)/3),l=o*o,h=n.index,m=n.attributes.position;if(h!==null){let f=Math.max(0,a.start),v=Math.min(h.count,a.start+a.count);for(let S=f,E=v;S<E;S++){let _=h.getX(S);gs.fromBufferAttribute(m,_),Oh(gs,_,l,r,e,t,this)}}else{let f=Math.max(0,a.start),v=Math.min(m.count,a.start+a.count);for(let S=f,E=v;S<E;S++)gs.fromBufferAttribute(m,S),Oh(gs,S,l,r,e,t,this)}}updateMorphTargets(){let t=this.geometry.morphAttributes,n=Object.keys(t);if(n.length>0){let r=t[n[0]];if(r!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let s=0,a=r.length;s<a;s++){let o=r[s].name||String(s);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=s}}}}};function Oh(i,e,t,n,r,s,a){let o=Qo.distanceSqToPoint(i);if(o<t){let l=new X;Qo.closestPointToPoint(i,l),l.applyMatrix4(n);let h=r.ray.origin.distanceTo(l);if(h<r.near||h>r.far)return;s.push({distance:h,distanceToRay:Math.sqrt(o),point:l,index:e,face:null,faceIndex:null,barycoord:null,object:a})}}function vs(i,e,t){return!i||!t&&i.constructor===e?i:typeof e.BYTES_PER_ELEMENT=="number"?new e(i):Array.prototype.slice.call(i)}function W_(i){return ArrayBuffer.isView(i)&&!(i instanceof DataView)}var nr=class{constructor(e,t,n,r){this.parameterPositions=e,this._cachedIndex=0,this.resultBuffer=r!==void 0?r:new t.constructor(n),this.sampleValues=t,this.valueSize=n,this.settings=null,this.DefaultSettings_={}}evaluate(e){let t=this.parameterPositions,n=this._cachedIndex,r=t[n],s=t[n-1];n:{e:{let a;t:{i:if(!(e<r)){for(let o=n+2;;){if(r===void 0){if(e<s)break i;return n=t.length,this._cachedIndex=n,this.copySampleValue_(n-1)}if(n===o)break;if(s=r,r=t[++n],e<r)break e}a=t.length;break t}if(!(e>=s)){let o=t[1];e<o&&(n=2,s=o);for(let l=n-2;;){if(s===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(n===l)break;if(r=s,s=t[--n-1],e>=s)break e}a=n,n=0;break t}break n}for(;n<a;){let o=n+a>>>1;e<t[o]?a=o:n=o+1}if(r=t[n],s=t[n-1],s===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(r===void 0)return n=t.length,this._cachedIndex=n,this.copySampleValue_(n-1)}this._cachedIndex=n,this.intervalChanged_(n,s,r)}return this.interpolate_(n,s,e,r)}getSettings_(){return this.settings||this.DefaultSettings_}copySampleValue_(e){let t=this.resultBuffer,n=this.sampleValues,r=this.valueSize,s=e*r;for(let a=0;a!==r;++a)t[a]=n[s+a];return t}interpolate_(){throw new Error("call to abstract method")}intervalChanged_(){}},ec=class extends nr{constructor(e,t,n,r){super(e,t,n,r),this._weightPrev=-0,this._offsetPrev=-0,this._weightNext=-0,this._offsetNext=-0,this.DefaultSettings_={endingStart:Bl,endingEnd:Bl}}intervalChanged_(e,t,n){let r=this.parameterPositions,s=e-2,a=e+1,o=r[s],l=r[a];if(o===void 0)switch(this.getSettings_().endingStart){case zl:s=e,o=2*t-n;break;case Gl:s=r.length-2,o=t+r[s]-r[s+1];break;default:s=e,o=n}if(l===void 0)switch(this.getSettings_().endingEnd){case zl:a=e,l=2*n-t;break;case Gl:a=1,l=n+r[1]-r[0];break;default:a=e-1,l=t}let h=(n-t)*.5,d=this.valueSize;this._weightPrev=h/(t-o),this._weightNext=h/(l-n),this._offsetPrev=s*d,this._offsetNext=a*d}interpolate_(e,t,n,r){let s=this.resultBuffer,a=this.sampleValues,o=this.valueSize,l=e*o,h=l-o,d=this._offsetPrev,m=this._offsetNext,f=this._weightPrev,v=this._weightNext,S=(n-t)/(r-t),E=S*S,_=E*S,g=-f*_+2*f*E-f*S,I=(1+f)*_+(-1.5-2*f)*E+(-.5+f)*S+1,P=(-1-v)*_+(1.5+v)*E+.5*S,C=v*_-v*E;for(let H=0;H!==o;++H)s[H]=g*a[d+H]+I*a[h+H]+P*a[l+H]+C*a[m+H];return s}},tc=class extends nr{constructor(e,t,n,r){super(e,t,n,r)}interpolate_(e,t,n,r){let s=this.resultBuffer,a=this.sampleValues,o=this.valueSize,l=e*o,h=l-o,d=(n-t)/(r-t),m=1-d;for(let f=0;f!==o;++f)s[f]=a[h+f]*m+a[l+f]*d;return s}},nc=class extends nr{constructor(e,t,n,r){super(e,t,n,r)}interpolate_(e){return this.copySampleValue_(e-1)}},hn=class{constructor(e,t,n,r){if(e===void 0)throw new Error("THREE.KeyframeTrack: track name is undefined");if(t===void 0||t.length===0)throw new Error("THREE.KeyframeTrack: no keyframes in track named "+e);this.name=e,this.times=vs(t,this.TimeBufferType),this.values=vs(n,this.ValueBufferType),this.setInterpolation(r||this.DefaultInterpolation)}static toJSON(e){let t=e.constructor,n;if(t.toJSON!==this.toJSON)n=t.toJSON(e);else{n={name:e.name,times:vs(e.times,Array),values:vs(e.values,Array)};let r=e.getInterpolation();r!==e.DefaultInterpolation&&(n.interpolation=r)}return n.type=e.ValueTypeName,n}InterpolantFactoryMethodDiscrete(e){return new nc(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodLinear(e){return new tc(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodSmooth(e){return new ec(this.times,this.values,this.getValueSize(),e)}setInterpolation(e){let t;switch(e){case Ms:t=this.InterpolantFactoryMethodDiscrete;break;case Uo:t=this.InterpolantFactoryMethodLinear;break;case Sa:t=this.InterpolantFactoryMethodSmooth;break}if(t===void 0){let n="unsupported interpolation for "+this.ValueTypeName+" keyframe track named "+this.name;if(this.createInterpolant===void 0)if(e!==this.DefaultInterpolation)this.setInterpolation(this.DefaultInterpolation);else throw new Error(n);return console.warn("THREE.KeyframeTrack:",n),this}return this.createInterpolant=t,this}getInterpolation(){switch(this.createInterpolant){case this.InterpolantFactoryMethodDiscrete:return Ms;case this.InterpolantFactoryMethodLinear:return Uo;case this.InterpolantFactoryMethodSmooth:return Sa}}getValueSize(){return this.values.length/this.times.length}shift(e){if(e!==0){let t=this.times;for(let n=0,r=t.length;n!==r;++n)t[n]+=e}return this}scale(e){if(e!==1){let t=this.times;for(let n=0,r=t.length;n!==r;++n)t[n]*=e}return this}trim(e,t){let n=this.times,r=n.length,s=0,a=r-1;for(;s!==r&&n[s]<e;)++s;for(;a!==-1&&n[a]>t;)--a;if(++a,s!==0||a!==r){s>=a&&(a=Math.max(a,1),s=a-1);let o=this.getValueSize();this.times=n.slice(s,a),this.values=this.values.slice(s*o,a*o)}return this}validate(){let e=!0,t=this.getValueSize();t-Math.floor(t)!==0&&(console.error("THREE.KeyframeTrack: Invalid value size in track.",this),e=!1);let n=this.times,r=this.values,s=n.length;s===0&&(console.error("THREE.KeyframeTrack: Track is empty.",this),e=!1);let a=null;for(let o=0;o!==s;o++){let l=n[o];if(typeof l=="number"&&isNaN(l)){console.error("THREE.KeyframeTrack: Time is not a valid number.",this,o,l),e=!1;break}if(a!==null&&a>l){console.error("THREE.KeyframeTrack: Out of order keys.",this,o,l,a),e=!1;break}a=l}if(r!==void 0&&W_(r))for(let o=0,l=r.length;o!==l;++o){let h=r[o];if(isNaN(h)){console.error("THREE.KeyframeTrack: Value is not a valid number.",this,o,h),e=!1;break}}return e}optimize(){let e=this.times.slice(),t=this.values.slice(),n=this.getValueSize(),r=this.getInterpolation()===Sa,s=e.length-1,a=1;for(let o=1;o<s;++o){let l=!1,h=e[o],d=e[o+1];if(h!==d&&(o!==1||h!==e[0]))if(r)l=!0;else{let m=o*n,f=m-n,v=m+n;for(let S=0;S!==n;++S){let E=t[m+S];if(E!==t[f+S]||E!==t[v+S]){l=!0;break}}}if(l){if(o!==a){e[a]=e[o];let m=o*n,f=a*n;for(let v=0;v!==n;++v)t[f+v]=t[m+v]}++a}}if(s>0){e[a]=e[s];for(let o=s*n,l=a*n,h=0;h!==n;++h)t[l+h]=t[o+h];++a}return a!==e.length?(this.times=e.slice(0,a),this.values=t.slice(0,a*n)):(this.times=e,this.values=t),this}clone(){let e=this.times.slice(),t=this.values.slice(),n=this.constructor,r=new n(this.name,e,t);return r.createInterpolant=this.createInterpolant,r}};hn.prototype.TimeBufferType=Float32Array;hn.prototype.ValueBufferType=Float32Array;hn.prototype.DefaultInterpolation=Uo;var vi=class extends hn{constructor(e,t,n){super(e,t,n)}};vi.prototype.ValueTypeName="bool";vi.prototype.ValueBufferType=Array;vi.prototype.DefaultInterpolation=Ms;vi.prototype.InterpolantFactoryMethodLinear=void 0;vi.prototype.InterpolantFactoryMethodSmooth=void 0;var ic=class extends hn{};ic.prototype.ValueTypeName="color";var rc=class extends hn{};rc.prototype.ValueTypeName="number";var sc=class extends nr{constructor(e,t,n,r){super(e,t,n,r)}interpolate_(e,t,n,r){let s=this.resultBuffer,a=this.sampleValues,o=this.valueSize,l=(n-t)/(r-t),h=e*o;for(let d=h+o;h!==d;h+=4)ln.slerpFlat(s,0,a,h-o,a,h,l);return s}},Gs=class extends hn{InterpolantFactoryMethodLinear(e){return new sc(this.times,this.values,this.getValueSize(),e)}};Gs.prototype.ValueTypeName="quaternion";Gs.prototype.InterpolantFactoryMethodSmooth=void 0;var _i=class extends hn{constructor(e,t,n){super(e,t,n)}};_i.prototype.ValueTypeName="string";_i.prototype.ValueBufferType=Array;_i.prototype.DefaultInterpolation=Ms;_i.prototype.InterpolantFactoryMethodLinear=void 0;_i.prototype.InterpolantFactoryMethodSmooth=void 0;var ac=class extends hn{};ac.prototype.ValueTypeName="vector";var oc=class{constructor(e,t,n){let r=this,s=!1,a=0,o=0,l,h=[];this.onStart=void 0,this.onLoad=e,this.onProgress=t,this.onError=n,this.itemStart=function(d){o++,s===!1&&r.onStart!==void 0&&r.onStart(d,a,o),s=!0},this.itemEnd=function(d){a++,r.onProgress!==void 0&&r.onProgress(d,a,o),a===o&&(s=!1,r.onLoad!==void 0&&r.onLoad())},this.itemError=function(d){r.onError!==void 0&&r.onError(d)},this.resolveURL=function(d){return l?l(d):d},this.setURLModifier=function(d){return l=d,this},this.addHandler=function(d,m){return h.push(d,m),this},this.removeHandler=function(d){let m=h.indexOf(d);return m!==-1&&h.splice(m,2),this},this.getHandler=function(d){for(let m=0,f=h.length;m<f;m+=2){let v=h[m],S=h[m+1];if(v.global&&(v.lastIndex=0),v.test(d))return S}return null}}},X_=new oc,cc=class{constructor(e){this.manager=e!==void 0?e:X_,this.crossOrigin="anonymous",this.withCredentials=!1,this.path="",this.resourcePath="",this.requestHeader={}}load(){}loadAsync(e,t){let n=this;return new Promise(function(r,s){n.load(e,r,t,s)})}parse(){}setCrossOrigin(e){return this.crossOrigin=e,this}setWithCredentials(e){return this.withCredentials=e,this}setPath(e){return this.path=e,this}setResourcePath(e){return this.resourcePath=e,this}setRequestHeader(e){return this.requestHeader=e,this}};cc.DEFAULT_MATERIAL_NAME="__DEFAULT";var yc="\\[\\]\\.:\\/",q_=new RegExp("["+yc+"]","g"),xc="[^"+yc+"]",Y_="[^"+yc.replace("\\.","")+"]",Z_=/((?:WC+[\/:])*)/.source.replace("WC",xc),$_=/(WCOD+)?/.source.replace("WCOD",Y_),K_=/(?:\.(WC+)(?:\[(.+)\])?)?/.source.replace("WC",xc),j_=/\.(WC+)(?:\[(.+)\])?/.source.replace("WC",xc),J_=new RegExp("^"+Z_+$_+K_+j_+"$"),Q_=["material","materials","bones","map"],lc=class{constructor(e,t,n){let r=n||pt.parseTrackName(t);this._targetGroup=e,this._bindings=e.subscribe_(t,r)}getValue(e,t){this.bind();let n=this._targetGroup.nCachedObjects_,r=this._bindings[n];r!==void 0&&r.getValue(e,t)}setValue(e,t){let n=this._bindings;for(let r=this._targetGroup.nCachedObjects_,s=n.length;r!==s;++r)n[r].setValue(e,t)}bind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,n=e.length;t!==n;++t)e[t].bind()}unbind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,n=e.length;t!==n;++t)e[t].unbind()}},pt=class i{constructor(e,t,n){this.path=t,this.parsedPath=n||i.parseTrackName(t),this.node=i.findNode(e,this.parsedPath.nodeName),this.rootNode=e,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}static create(e,t,n){return e&&e.isAnimationObjectGroup?new i.Composite(e,t,n):new i(e,t,n)}static sanitizeNodeName(e){return e.replace(/\s/g,"_").replace(q_,"")}static parseTrackName(e){let t=J_.exec(e);if(t===null)throw new Error("PropertyBinding: Cannot parse trackName: "+e);let n={nodeName:t[2],objectName:t[3],objectIndex:t[4],propertyName:t[5],propertyIndex:t[6]},r=n.nodeName&&n.nodeName.lastIndexOf(".");if(r!==void 0&&r!==-1){let s=n.nodeName.substring(r+1);Q_.indexOf(s)!==-1&&(n.nodeName=n.nodeName.substring(0,r),n.objectName=s)}if(n.propertyName===null||n.propertyName.length===0)throw new Error("PropertyBinding: can not parse propertyName from trackName: "+e);return n}static findNode(e,t){if(t===void 0||t===""||t==="."||t===-1||t===e.name||t===e.uuid)return e;if(e.skeleton){let n=e.skeleton.getBoneByName(t);if(n!==void 0)return n}if(e.children){let n=function(s){for(let a=0;a<s.length;a++){let o=s[a];if(o.name===t||o.uuid===t)return o;let l=n(o.children);if(l)return l}return null},r=n(e.children);if(r)return r}return null}_getValue_unavailable(){}_setValue_unavailable(){}_getValue_direct(e,t){e[t]=this.targetObject[this.propertyName]}_getValue_array(e,t){let n=this.resolvedProperty;for(let r=0,s=n.length;r!==s;++r)e[t++]=n[r]}_getValue_arrayElement(e,t){e[t]=this.resolvedProperty[this.propertyIndex]}_getValue_toArray(e,t){this.resolvedProperty.toArray(e,t)}_setValue_direct(e,t){this.targetObject[this.propertyName]=e[t]}_setValue_direct_setNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.needsUpdate=!0}_setValue_direct_setMatrixWorldNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_array(e,t){let n=this.resolvedProperty;for(let r=0,s=n.length;r!==s;++r)n[r]=e[t++]}_setValue_array_setNeedsUpdate(e,t){let n=this.resolvedProperty;for(let r=0,s=n.length;r!==s;++r)n[r]=e[t++];this.targetObject.needsUpdate=!0}_setValue_array_setMatrixWorldNeedsUpdate(e,t){let n=this.resolvedProperty;for(let r=0,s=n.length;r!==s;++r)n[r]=e[t++];this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_arrayElement(e,t){this.resolvedProperty[this.propertyIndex]=e[t]}_setValue_arrayElement_setNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.needsUpdate=!0}_setValue_arrayElement_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_fromArray(e,t){this.resolvedProperty.fromArray(e,t)}_setValue_fromArray_setNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.needsUpdate=!0}_setValue_fromArray_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.matrixWorldNeedsUpdate=!0}_getValue_unbound(e,t){this.bind(),this.getValue(e,t)}_setValue_unbound(e,t){this.bind(),this.setValue(e,t)}bind(){let e=this.node,t=this.parsedPath,n=t.objectName,r=t.propertyName,s=t.propertyIndex;if(e||(e=i.findNode(this.rootNode,t.nodeName),this.node=e),this.getValue=this._getValue_unavailable,this.setValue=this._setValue_unavailable,!e){console.warn("THREE.PropertyBinding: No target node found for track: "+this.path+".");return}if(n){let h=t.objectIndex;switch(n){case"materials":if(!e.material){console.error("THREE.PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.materials){console.error("THREE.PropertyBinding: Can not bind to material.materials as node.material does not have a materials array.",this);return}e=e.material.materials;break;case"bones":if(!e.skeleton){console.error("THREE.PropertyBinding: Can not bind to bones as node does not have a skeleton.",this);return}e=e.skeleton.bones;for(let d=0;d<e.length;d++)if(e[d].name===h){h=d;break}break;case"map":if("map"in e){e=e.map;break}if(!e.material){console.error("THREE.PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.map){console.error("THREE.PropertyBinding: Can not bind to material.map as node.material does not have a map.",this);return}e=e.material.map;break;default:if(e[n]===void 0){console.error("THREE.PropertyBinding: Can not bind to objectName of node undefined.",this);return}e=e[n]}if(h!==void 0){if(e[h]===void 0){console.error("THREE.PropertyBinding: Trying to bind to objectIndex of objectName, but is undefined.",this,e);return}e=e[h]}}let a=e[r];if(a===void 0){let h=t.nodeName;console.error("THREE.PropertyBinding: Trying to update property for track: "+h+"."+r+" but it wasn't found.",e);return}let o=this.Versioning.None;this.targetObject=e,e.needsUpdate!==void 0?o=this.Versioning.NeedsUpdate:e.matrixWorldNeedsUpdate!==void 0&&(o=this.Versioning.MatrixWorldNeedsUpdate);let l=this.BindingType.Direct;if(s!==void 0){if(r==="morphTargetInfluences"){if(!e.geometry){console.error("THREE.PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.",this);return}if(!e.geometry.morphAttributes){console.error("THREE.PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.morphAttributes.",this);return}e.morphTargetDictionary[s]!==void 0&&(s=e.morphTargetDictionary[s])}l=this.BindingType.ArrayElement,this.resolvedProperty=a,this.propertyIndex=s}else a.fromArray!==void 0&&a.toArray!==void 0?(l=this.BindingType.HasFromToArray,this.resolvedProperty=a):Array.isArray(a)?(l=this.BindingType.EntireArray,this.resolvedProperty=a):this.propertyName=r;this.getValue=this.GetterByBindingType[l],this.setValue=this.SetterByBindingTypeAndVersioning[l][o]}unbind(){this.node=null,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}};pt.Composite=lc;pt.prototype.BindingType={Direct:0,EntireArray:1,ArrayElement:2,HasFromToArray:3};pt.prototype.Versioning={None:0,NeedsUpdate:1,MatrixWorldNeedsUpdate:2};pt.prototype.GetterByBindingType=[pt.prototype._getValue_direct,pt.prototype._getValue_array,pt.prototype._getValue_arrayElement,pt.prototype._getValue_toArray];pt.prototype.SetterByBindingTypeAndVersioning=[[pt.prototype._setValue_direct,pt.prototype._setValue_direct_setNeedsUpdate,pt.prototype._setValue_direct_setMatrixWorldNeedsUpdate],[pt.prototype._setValue_array,pt.prototype._setValue_array_setNeedsUpdate,pt.prototype._setValue_array_setMatrixWorldNeedsUpdate],[pt.prototype._setValue_arrayElement,pt.prototype._setValue_arrayElement_setNeedsUpdate,pt.prototype._setValue_arrayElement_setMatrixWorldNeedsUpdate],[pt.prototype._setValue_fromArray,pt.prototype._setValue_fromArray_setNeedsUpdate,pt.prototype._setValue_fromArray_setMatrixWorldNeedsUpdate]];var i0=new Float32Array(1);var Lr=class{constructor(e=1,t=0,n=0){return this.radius=e,this.phi=t,this.theta=n,this}set(e,t,n){return this.radius=e,this.phi=t,this.theta=n,this}copy(e){return this.radius=e.radius,this.phi=e.phi,this.theta=e.theta,this}makeSafe(){return this.phi=Math.max(1e-6,Math.min(Math.PI-1e-6,this.phi)),this}setFromVector3(e){return this.setFromCartesianCoords(e.x,e.y,e.z)}setFromCartesianCoords(e,t,n){return this.radius=Math.sqrt(e*e+t*t+n*n),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(e,n),this.phi=Math.acos(Rt(t/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}};var Vs=class extends Pn{constructor(e,t=null){super(),this.object=e,this.domElement=t,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(){}disconnect(){}dispose(){}update(){}};typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:hc}}));typeof window<"u"&&(window.__THREE__?console.warn("WARNING: Multiple instances of Three.js being imported."):window.__THREE__=hc);var ou={type:"change"},Sc={type:"start"},lu={type:"end"},qs=new er,cu=new rn,ty=Math.cos(70*Jh.DEG2RAD),Mt=new X,Bt=2*Math.PI,lt={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},bc=1e-6,Ys=class extends Vs{constructor(e,t=null){super(e,t),this.state=lt.NONE,this.enabled=!0,this.target=new X,this.cursor=new X,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:yi.ROTATE,MIDDLE:yi.DOLLY,RIGHT:yi.PAN},this.touches={ONE:xi.ROTATE,TWO:xi.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._domElementKeyEvents=null,this._lastPosition=new X,this._lastQuaternion=new ln,this._lastTargetPosition=new X,this._quat=new ln().setFromUnitVectors(e.up,new X(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new Lr,this._sphericalDelta=new Lr,this._scale=1,this._panOffset=new X,this._rotateStart=new $e,this._rotateEnd=new $e,this._rotateDelta=new $e,this._panStart=new $e,this._panEnd=new $e,this._panDelta=new $e,this._dollyStart=new $e,this._dollyEnd=new $e,this._dollyDelta=new $e,this._dollyDirection=new X,this._mouse=new $e,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=iy.bind(this),this._onPointerDown=ny.bind(this),this._onPointerUp=ry.bind(this),this._onContextMenu=uy.bind(this),this._onMouseWheel=oy.bind(this),this._onKeyDown=cy.bind(this),this._onTouchStart=ly.bind(this),this._onTouchMove=hy.bind(this),this._onMouseDown=sy.bind(this),this._onMouseMove=ay.bind(this),this._interceptControlDown=dy.bind(this),this._interceptControlUp=fy.bind(this),this.domElement!==null&&this.connect(),this.update()}connect(){this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.getRootNode().addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.removeEventListener("pointermove",this._onPointerMove),this.domElement.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.getRootNode().removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.style.touchAction="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(e){e.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=e}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(ou),this.update(),this.state=lt.NONE}update(e=null){let t=this.object.position;Mt.copy(t).sub(this.target),Mt.applyQuaternion(this._quat),this._spherical.setFromVector3(Mt),this.autoRotate&&this.state===lt.NONE&&this._rotateLeft(this._getAutoRotationAngle(e)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let n=this.minAzimuthAngle,r=this.maxAzimuthAngle;isFinite(n)&&isFinite(r)&&(n<-Math.PI?n+=Bt:n>Math.PI&&(n-=Bt),r<-Math.PI?r+=Bt:r>Math.PI&&(r-=Bt),n<=r?this._spherical.theta=Math.max(n,Math.min(r,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(n+r)/2?Math.max(n,this._spherical.theta):Math.min(r,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let s=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{let a=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),s=a!=this._spherical.radius}if(Mt.setFromSpherical(this._spherical),Mt.applyQuaternion(this._quatInverse),t.copy(this.target).add(Mt),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let a=null;if(this.object.isPerspectiveCamera){let o=Mt.length();a=this._clampDistance(o*this._scale);let l=o-a;this.object.position.addScaledVector(this._dollyDirection,l),this.object.updateMatrixWorld(),s=!!l}else if(this.object.isOrthographicCamera){let o=new X(this._mouse.x,this._mouse.y,0);o.unproject(this.object);let l=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),s=l!==this.object.zoom;let h=new X(this._mouse.x,this._mouse.y,0);h.unproject(this.object),this.object.position.sub(h).add(o),this.object.updateMatrixWorld(),a=Mt.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;a!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(a).add(this.object.position):(qs.origin.copy(this.object.position),qs.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(qs.direction))<ty?this.object.lookAt(this.target):(cu.setFromNormalAndCoplanarPoint(this.object.up,this.target),qs.intersectPlane(cu,this.target))))}else if(this.object.isOrthographicCamera){let a=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),a!==this.object.zoom&&(this.object.updateProjectionMatrix(),s=!0)}return this._scale=1,this._performCursorZoom=!1,s||this._lastPosition.distanceToSquared(this.object.position)>bc||8*(1-this._lastQuaternion.dot(this.object.quaternion))>bc||this._lastTargetPosition.distanceToSquared(this.target)>bc?(this.dispatchEvent(ou),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(e){return e!==null?Bt/60*this.autoRotateSpeed*e:Bt/60/60*this.autoRotateSpeed}_getZoomScale(e){let t=Math.abs(e*.01);return Math.pow(.95,this.zoomSpeed*t)}_rotateLeft(e){this._sphericalDelta.theta-=e}_rotateUp(e){this._sphericalDelta.phi-=e}_panLeft(e,t){Mt.setFromMatrixColumn(t,0),Mt.multiplyScalar(-e),this._panOffset.add(Mt)}_panUp(e,t){this.screenSpacePanning===!0?Mt.setFromMatrixColumn(t,1):(Mt.setFromMatrixColumn(t,0),Mt.crossVectors(this.object.up,Mt)),Mt.multiplyScalar(e),this._panOffset.add(Mt)}_pan(e,t){let n=this.domElement;if(this.object.isPerspectiveCamera){let r=this.object.position;Mt.copy(r).sub(this.target);let s=Mt.length();s*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*e*s/n.clientHeight,this.object.matrix),this._panUp(2*t*s/n.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(e*(this.object.right-this.object.left)/this.object.zoom/n.clientWidth,this.object.matrix),this._panUp(t*(this.object.top-this.object.bottom)/this.object.zoom/n.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(e,t){if(!this.zoomToCursor)return;this._performCursorZoom=!0;let n=this.domElement.getBoundingClientRect(),r=e-n.left,s=t-n.top,a=n.width,o=n.height;this._mouse.x=r/a*2-1,this._mouse.y=-(s/o)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(e){return Math.max(this.minDistance,Math.min(this.maxDistance,e))}_handleMouseDownRotate(e){this._rotateStart.set(e.clientX,e.clientY)}_handleMouseDownDolly(e){this._updateZoomParameters(e.clientX,e.clientX),this._dollyStart.set(e.clientX,e.clientY)}_handleMouseDownPan(e){this._panStart.set(e.clientX,e.clientY)}_handleMouseMoveRotate(e){this._rotateEnd.set(e.clientX,e.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(Bt*this._rotateDelta.x/t.clientHeight),this._rotateUp(Bt*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(e){this._dollyEnd.set(e.clientX,e.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.update()}_handleMouseMovePan(e){this._panEnd.set(e.clientX,e.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(e){this._updateZoomParameters(e.clientX,e.clientY),e.deltaY<0?this._dollyIn(this._getZoomScale(e.deltaY)):e.deltaY>0&&this._dollyOut(this._getZoomScale(e.deltaY)),this.update()}_handleKeyDown(e){let t=!1;switch(e.code){case this.keys.UP:e.ctrlKey||e.metaKey||e.shiftKey?this._rotateUp(Bt*this.rotateSpeed/this.domElement.clientHeight):this._pan(0,this.keyPanSpeed),t=!0;break;case this.keys.BOTTOM:e.ctrlKey||e.metaKey||e.shiftKey?this._rotateUp(-Bt*this.rotateSpeed/this.domElement.clientHeight):this._pan(0,-this.keyPanSpeed),t=!0;break;case this.keys.LEFT:e.ctrlKey||e.metaKey||e.shiftKey?this._rotateLeft(Bt*this.rotateSpeed/this.domElement.clientHeight):this._pan(this.keyPanSpeed,0),t=!0;break;case this.keys.RIGHT:e.ctrlKey||e.metaKey||e.shiftKey?this._rotateLeft(-Bt*this.rotateSpeed/this.domElement.clientHeight):this._pan(-this.keyPanSpeed,0),t=!0;break}t&&(e.preventDefault(),this.update())}_handleTouchStartRotate(e){if(this._pointers.length===1)this._rotateStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),r=.5*(e.pageY+t.y);this._rotateStart.set(n,r)}}_handleTouchStartPan(e){if(this._pointers.length===1)this._panStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),r=.5*(e.pageY+t.y);this._panStart.set(n,r)}}_handleTouchStartDolly(e){let t=this._getSecondPointerPosition(e),n=e.pageX-t.x,r=e.pageY-t.y,s=Math.sqrt(n*n+r*r);this._dollyStart.set(0,s)}_handleTouchStartDollyPan(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enablePan&&this._handleTouchStartPan(e)}_handleTouchStartDollyRotate(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enableRotate&&this._handleTouchStartRotate(e)}_handleTouchMoveRotate(e){if(this._pointers.length==1)this._rotateEnd.set(e.pageX,e.pageY);else{let n=this._getSecondPointerPosition(e),r=.5*(e.pageX+n.x),s=.5*(e.pageY+n.y);this._rotateEnd.set(r,s)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(Bt*this._rotateDelta.x/t.clientHeight),this._rotateUp(Bt*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(e){if(this._pointers.length===1)this._panEnd.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),r=.5*(e.pageY+t.y);this._panEnd.set(n,r)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(e){let t=this._getSecondPointerPosition(e),n=e.pageX-t.x,r=e.pageY-t.y,s=Math.sqrt(n*n+r*r);this._dollyEnd.set(0,s),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);let a=(e.pageX+t.x)*.5,o=(e.pageY+t.y)*.5;this._updateZoomParameters(a,o)}_handleTouchMoveDollyPan(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enablePan&&this._handleTouchMovePan(e)}_handleTouchMoveDollyRotate(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enableRotate&&this._handleTouchMoveRotate(e)}_addPointer(e){this._pointers.push(e.pointerId)}_removePointer(e){delete this._pointerPositions[e.pointerId];for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId){this._pointers.splice(t,1);return}}_isTrackingPointer(e){for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId)return!0;return!1}_trackPointer(e){let t=this._pointerPositions[e.pointerId];t===void 0&&(t=new $e,this._pointerPositions[e.pointerId]=t),t.set(e.pageX,e.pageY)}_getSecondPointerPosition(e){let t=e.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[t]}_customWheelEvent(e){let t=e.deltaMode,n={clientX:e.clientX,clientY:e.clientY,deltaY:e.deltaY};switch(t){case 1:n.deltaY*=16;break;case 2:n.deltaY*=100;break}return e.ctrlKey&&!this._controlActive&&(n.deltaY*=10),n}};function ny(i){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(i.pointerId),this.domElement.addEventListener("pointermove",this._onPointerMove),this.domElement.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(i)&&(this._addPointer(i),i.pointerType==="touch"?this._onTouchStart(i):this._onMouseDown(i)))}function iy(i){this.enabled!==!1&&(i.pointerType==="touch"?this._onTouchMove(i):this._onMouseMove(i))}function ry(i){switch(this._removePointer(i),this._pointers.length){case 0:this.domElement.releasePointerCapture(i.pointerId),this.domElement.removeEventListener("pointermove",this._onPointerMove),this.domElement.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(lu),this.state=lt.NONE;break;case 1:let e=this._pointers[0],t=this._pointerPositions[e];this._onTouchStart({pointerId:e,pageX:t.x,pageY:t.y});break}}function sy(i){let e;switch(i.button){case 0:e=this.mouseButtons.LEFT;break;case 1:e=this.mouseButtons.MIDDLE;break;case 2:e=this.mouseButtons.RIGHT;break;default:e=-1}switch(e){case yi.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(i),this.state=lt.DOLLY;break;case yi.ROTATE:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=lt.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=lt.ROTATE}break;case yi.PAN:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=lt.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=lt.PAN}break;default:this.state=lt.NONE}this.state!==lt.NONE&&this.dispatchEvent(Sc)}function ay(i){switch(this.state){case lt.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(i);break;case lt.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(i);break;case lt.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(i);break}}function oy(i){this.enabled===!1||this.enableZoom===!1||this.state!==lt.NONE||(i.preventDefault(),this.dispatchEvent(Sc),this._handleMouseWheel(this._customWheelEvent(i)),this.dispatchEvent(lu))}function cy(i){this.enabled===!1||this.enablePan===!1||this._handleKeyDown(i)}function ly(i){switch(this._trackPointer(i),this._pointers.length){case 1:switch(this.touches.ONE){case xi.ROTATE:if(this.enableRotate===!1)return;this._handleTouchStartRotate(i),this.state=lt.TOUCH_ROTATE;break;case xi.PAN:if(this.enablePan===!1)return;this._handleTouchStartPan(i),this.state=lt.TOUCH_PAN;break;default:this.state=lt.NONE}break;case 2:switch(this.touches.TWO){case xi.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(i),this.state=lt.TOUCH_DOLLY_PAN;break;case xi.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(i),this.state=lt.TOUCH_DOLLY_ROTATE;break;default:this.state=lt.NONE}break;default:this.state=lt.NONE}this.state!==lt.NONE&&this.dispatchEvent(Sc)}function hy(i){switch(this._trackPointer(i),this.state){case lt.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(i),this.update();break;case lt.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(i),this.update();break;case lt.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(i),this.update();break;case lt.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(i),this.update();break;default:this.state=lt.NONE}}function uy(i){this.enabled!==!1&&i.preventDefault()}function dy(i){i.key==="Control"&&(this._controlActive=!0,this.domElement.getRootNode().addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function fy(i){i.key==="Control"&&(this._controlActive=!1,this.domElement.getRootNode().removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}var bi=null;function hu(i,e){let t=new pn;return t.setAttribute("position",new cn(i,3)),new zs(t,new Pr({color:e,size:1.5,sizeAttenuation:!1}))}function uu(i,e){if(!bi){let s=new ks({antialias:!0,preserveDrawingBuffer:!0});s.setSize(i.clientWidth||360,i.clientHeight||360),i.appendChild(s.domElement);let a=new Nt(40,1,.1,1e3);a.position.set(0,-30,30),a.up.set(0,0,1);let o=new Ys(a,s.domElement);bi={renderer:s,camera:a,controls:o,scene:null};let l=()=>{o.update(),bi.scene&&i.offsetParent!==null&&s.render(bi.scene,a),requestAnimationFrame(l)};l()}let t=new Bs;t.background=new tt(1118481),t.add(hu(e.target,13934688)),t.add(hu(e.source,5217256));let r=new In().setFromObject(t).getSize(new X).length()/2||10;bi.camera.position.set(0,-1.4*r,1.4*r),bi.controls.target.set(0,0,0),bi.scene=t}var py=new URLSearchParams(location.search),my=py.get("token")||"",Tc="tab-"+Math.random().toString(36).slice(2,10),du=["#1f77b4","#ff7f0e","#2ca02c","#d62728","#9467bd","#8c564b","#e377c2","#17becf","#bcbd22","#393b79","#637939","#8c6d31","#843c39","#7b4173","#3182bd","#e6550d","#31a354","#756bb1","#636363","#ad494a"],gy="#b9b2a6",vy=24,_y={auto:0,cut:1,forced:2,expert:3},Y={state:null,seq:0,tau:.95,graph:null,renderer:null,nodeIndex:new Map,src:null,dst:null,prob:null,edgeState:null,label:null,size:null,kept:null,links:null,selected:null,matches:null,verified:new Set,pairList:[],pairPos:0,pair:null,timings:[]};window.coindie=Y;var ve=i=>document.getElementById(i);async function Un(i,e={}){let t={"X-Coindie-Token":my,...e.body?{"Content-Type":"application/json"}:{}},n=await fetch(i,{...e,headers:t}),s=(n.headers.get("content-type")||"").includes("json")?await n.json():await n.text();if(!n.ok){let a=new Error(s.error||String(s));throw a.status=n.status,a}return s}function Jt(i,e=!1){let t=ve("toast");t.textContent=i,t.className="show"+(e?" error":""),clearTimeout(Jt.timer),Jt.timer=setTimeout(()=>t.className="",e?8e3:3e3)}function Si(i){let e=/^\s*L0*(\d+)([DR])\s*$/i.exec(i);return e?"L"+e[1].padStart(4,"0")+e[2].toUpperCase():i.trim()}function vu(){let i=Y.state.nodes.length,e=new Int32Array(i);for(let f=0;f<i;f++)e[f]=f;let t=f=>{for(;e[f]!==f;)e[f]=e[e[f]],f=e[f];return f},n=(f,v)=>{let S=t(f),E=t(v);S!==E&&(e[Math.max(S,E)]=Math.min(S,E))},r=Y.prob.length,s=new Uint8Array(r),a=Y.links!==null;if(a){let{src:f,dst:v,value:S}=Y.links;for(let E=0;E<S.length;E++)S[E]>Y.tau&&n(f[E],v[E])}for(let f=0;f<r;f++){let v=Y.edgeState[f];v!==1&&(v===2||!a&&Y.prob[f]>Y.tau)&&(s[f]=1,n(Y.src[f],Y.dst[f]))}let o=new Int32Array(i),l=new Int32Array(i);for(let f=0;f<i;f++)o[f]=t(f),l[o[f]]++;if(a)for(let f=0;f<r;f++)Y.edgeState[f]!==1&&o[Y.src[f]]===o[Y.dst[f]]&&(s[f]=1);for(let f=0;f<i;f++)l[f]=l[o[f]];Y.label=o,Y.size=l,Y.kept=s;let h=0,d=0;for(let f=0;f<i;f++)o[f]===f&&(h++,l[f]===1&&d++);Y.counts={clusters:h,singletons:d};let m=new Map;for(let f=0;f<i;f++)m.has(o[f])||m.set(o[f],[]),m.get(o[f]).push(Y.state.nodes[f].id);Y.verifiedNodes=new Uint8Array(i);for(let[f,v]of m)if(Y.verified.has(v.slice().sort().join(",")))for(let S of v)Y.verifiedNodes[Y.nodeIndex.get(S)]=1;ve("counts").textContent=`${h} clusters, ${d} singletons`}function _u(i){return Y.size[i]===1?gy:du[Y.label[i]*7919%du.length]}function ar(i){let e=Y.state.nodes[i],t=ve("filter-face").value;return!(t&&e.side!==t||Y.size[i]<(parseInt(ve("filter-size").value,10)||1)||ve("filter-unverified").checked&&Y.verifiedNodes[i])}function Mc(){let i=performance.now();vu(),Y.renderer.refresh({skipIndexation:!0});let e=performance.now()-i;requestAnimationFrame(()=>{Y.timings.push({computed:e,frame:performance.now()-i})})}async function Dr(){let i=await Un("/api/state");Y.state=i,Y.seq=i.seq,Y.verified=new Set(i.verified.map(t=>t.slice().sort().join(","))),ve("title").textContent="coindie \xB7 "+i.name;let e=i.edges.length;if(Y.src=new Int32Array(e),Y.dst=new Int32Array(e),Y.prob=new Float32Array(e),Y.edgeState=new Uint8Array(e),i.edges.forEach(([t,n,r,s],a)=>{Y.src[a]=t,Y.dst[a]=n,Y.prob[a]=r,Y.edgeState[a]=_y[s]}),Y.links=null,i.links){let t=i.links.length;Y.links={src:new Int32Array(t),dst:new Int32Array(t),value:new Float64Array(t)},i.links.forEach(([n,r,s],a)=>{Y.links.src[a]=n,Y.links.dst[a]=r,Y.links.value[a]=s})}ve("threshold-label").title=i.links?`Each side's clusters as coindie cluster --auto cuts them at ${i.threshold} (${i.how}); right: stricter, left: looser`:"Links with a probability above \u03C4 count",ve("threshold-name").textContent=i.links?"cut":"\u03C4",Y.nodeIndex=new Map(i.nodes.map((t,n)=>[t.id,n])),vu(),yy(),Mc(),Y.selected&&Ks(Y.selected),ve("undo").disabled=i.undo_target==null,ve("redo").disabled=i.redo_target==null}function yy(){let i=new gu.default({type:"undirected",multi:!0}),t=Y.state.nodes.length>500?3:6;Y.state.nodes.forEach(n=>i.addNode(n.id,{x:n.x,y:n.y,size:t,label:n.id}));for(let n=0;n<Y.prob.length;n++)i.addEdgeWithKey(String(n),Y.state.nodes[Y.src[n]].id,Y.state.nodes[Y.dst[n]].id,{e:n});Y.renderer?Y.renderer.setGraph(i):(Y.renderer=new Nl(i,ve("graph"),{labelRenderedSizeThreshold:9,zIndex:!0,preserveDrawingBuffer:!0,nodeReducer:(n,r)=>{let s=Y.nodeIndex.get(n),a={...r,color:_u(s)};return ar(s)||(a.hidden=!0),Y.matches&&!Y.matches.has(n)&&(a.color="#e4e0da",a.label=""),n===Y.selected&&(a.highlighted=!0,a.size=r.size*1.8,a.zIndex=2),Y.verifiedNodes&&Y.verifiedNodes[s]&&(a.size=(a.size||r.size)*1.3),a},edgeReducer:(n,r)=>{let s=r.e,a=Y.edgeState[s];return!Y.kept[s]||!ar(Y.src[s])||!ar(Y.dst[s])?{...r,hidden:!0}:{...r,color:a===2?"#2a8a2a":a===3?"#aa7700":"#9c9588",size:a===2?2:1}}}),Y.renderer.on("clickNode",({node:n})=>Ks(n)),Y.renderer.on("enterNode",({node:n,event:r})=>xy(n,r)),Y.renderer.on("leaveNode",()=>ve("hover").style.display="none")),Y.graph=i}function xy(i,e){if(!Y.state.has_images)return;let t=ve("hover");t.src=`/api/faces/${encodeURIComponent(i)}/thumbnail.png`;let n=ve("graph").getBoundingClientRect();t.style.left=n.left+e.x+16+"px",t.style.top=n.top+e.y+16+"px",t.style.display="block"}async function Ks(i){Y.selected=i,Y.renderer.refresh();let e;try{e=await Un(`/api/faces/${encodeURIComponent(i)}?threshold=${Y.tau}`)}catch(s){Jt(s.message,!0);return}let t=ve("panel"),n=s=>Y.state.has_images?`<img loading="lazy" src="/api/faces/${encodeURIComponent(s)}/thumbnail.png" alt="">`:"",r=e.neighbours.slice(0,vy).map(s=>`<tr class="neighbour" data-face="${s.face}"><td>${n(s.face)}</td><td class="state-${s.state}">${s.face}</td><td>${s.probability.toFixed(3)}</td><td>${s.state==="auto"?"":s.state}</td></tr>`).join("");t.innerHTML=`<h2 id="face-id">${e.face}</h2>
    ${Y.state.has_images?`<img class="thumb" src="/api/faces/${encodeURIComponent(e.face)}/thumbnail.png" alt="relief">`:"<p class='hint'>no image (bare graph)</p>"}
    <p>Cluster of ${e.cluster.length}${e.verified?" \xB7 <b>verified</b>":""}:</p>
    <p class="members">${e.cluster.map(s=>`<span data-face="${s}">${s}</span>`).join("")}</p>
    <p><button id="verify">Mark cluster verified</button> <button id="isolate">Make singleton</button>
      <button id="move">Move to cluster of\u2026</button> <button id="split">Split off\u2026</button></p>
    <h3>Neighbours (by probability)</h3>
    <table id="neighbours">${r}</table>`,t.querySelectorAll("tr.neighbour").forEach((s,a)=>s.addEventListener("click",()=>yu(e.face,e.neighbours.map(o=>o.face),a))),t.querySelectorAll(".members span").forEach(s=>s.addEventListener("click",()=>Ks(s.dataset.face))),ve("verify").onclick=()=>Nn("verify",e.face,null,{members:e.cluster}),ve("isolate").onclick=()=>Nn("move",e.face,null),ve("move").onclick=()=>{let s=prompt("Move "+e.face+" to the cluster of which face?");s&&Nn("move",e.face,Si(s))},ve("split").onclick=()=>{let s=prompt("Faces that leave this cluster (with "+e.face+"), separated by spaces:",e.face);if(!s)return;let a=s.split(/[\s,]+/).filter(Boolean).map(Si),o=e.cluster.filter(l=>!a.includes(l));Nn("split",e.face,null,{group:a,rest:o})},ve("link-a").value=e.face}async function Nn(i,e,t,n={}){try{let r=await Un("/api/edits",{method:"POST",body:JSON.stringify({action:i,a:e,b:t,payload:n,base_seq:Y.seq,client:Tc,threshold:Y.tau})});return Jt(`saved: edit ${r.edit.edit_id} (${i}${e?" "+e:""}${t?" "+t:""})`),await Dr(),r}catch(r){return Jt(r.message,!0),r.status===409&&await Dr(),null}}async function wc(){if(Y.pollPaused){setTimeout(wc,1500);return}try{let i=await Un(`/api/edits?since=${Y.seq}`);if(i.seq>Y.seq){let e=i.edits.filter(t=>t.payload.client!==Tc).length;await Dr(),e&&Jt(`${e} new edit(s) from another tab or user`)}}catch{}setTimeout(wc,1500)}function fu(i){let e=i.trim();if(!e){Y.matches=null,Y.renderer.refresh();return}let t=Si(e),n=Y.nodeIndex.has(t)?[t]:[],r=e.toLowerCase(),s=n.length?n:Y.state.nodes.map(a=>a.id).filter(a=>a.toLowerCase().includes(r));if(Y.matches=new Set(s),Y.renderer.refresh(),s.length){let a=Y.renderer.getNodeDisplayData(s[0]);a&&Y.renderer.getCamera().animate({x:a.x,y:a.y,ratio:.25},{duration:300}),s.length===1&&Ks(s[0])}else Jt(`no face matches ${e}`,!0)}async function yu(i,e,t){Y.pairList=e,Y.pairPos=t,await Ac(i,e[t])}async function Ac(i,e){let t;try{t=await Un(`/api/pairs/${encodeURIComponent(i)}/${encodeURIComponent(e)}`)}catch(s){Jt(s.message,!0);return}Y.pair={a:i,b:e,info:t},ve("pair").hidden=!1,ve("fix").hidden=!0,ve("pair-title").textContent=`${t.target} \u2190 ${t.source}`,ve("pair-info").textContent=`p = ${t.probability.toFixed(3)} \xB7 ${t.origin} \xB7 ${t.method}`+(t.valid?"":` \xB7 invalid: ${t.reason}`);let n=`/api/pairs/${encodeURIComponent(i)}/${encodeURIComponent(e)}`,r="?seq="+Y.seq;if(t.has_images){for(let s of["target","source","difference","heat"])ve("img-"+s).src=`${n}/${s}.png${r}`;ve("ov-target").src=`${n}/target.png${r}`,ve("ov-source").src=`${n}/source.png${r}`,ve("ov-source").style.opacity=ve("blend").value,Un(`${n}/clouds.json`).then(s=>uu(ve("three"),s)).catch(s=>Jt(s.message,!0))}by(t.histogram,t.max_distance_mm)}function by(i,e){let t=ve("histogram"),n=t.getContext("2d");if(n.clearRect(0,0,t.width,t.height),!i){n.fillText("no histogram (bare graph)",10,20);return}let r=Math.max(...i,1e-9),s=(t.width-30)/i.length,a=t.height-30;n.fillStyle="#8b5e34",i.forEach((o,l)=>n.fillRect(25+l*s,10+a-o/r*a,Math.max(s-1,1),o/r*a)),n.fillStyle="#333",n.fillText("0",22,t.height-6),n.fillText(e.toFixed(2)+" mm",t.width-50,t.height-6)}function Ec(i){!Y.pair||!Y.pairList.length||(Y.pairPos=(Y.pairPos+i+Y.pairList.length)%Y.pairList.length,Ac(Y.pair.a,Y.pairList[Y.pairPos]))}async function Zs(i){Y.pair&&(await Nn(i?"link":"cut",Y.pair.a,Y.pair.b),Ec(1))}var $s=null;function Sy(){if($s){clearInterval($s),$s=null,ve("ov-source").style.opacity=ve("blend").value;return}let i=!1;$s=setInterval(()=>{i=!i,ve("ov-source").style.opacity=i?1:0},400)}var jt={target:[],source:[]};function pu(){if(!Y.pair||!Y.pair.info.has_images){Jt("no scans: nothing to register",!0);return}let{target:i,source:e}=Y.pair.info;ve("fix").hidden=!1,jt.target=[],jt.source=[];for(let[t,n]of[["target",i],["source",e]]){let r=ve("pick-"+t);r.querySelectorAll(".mark").forEach(s=>s.remove()),r.querySelector("img").src=`/api/faces/${encodeURIComponent(n)}/relief.png`}Cc()}function mu(i,e){let t=ve("pick-"+i).querySelector("img"),n=t.getBoundingClientRect(),r=(e.clientX-n.left)*t.naturalWidth/n.width,s=(e.clientY-n.top)*t.naturalHeight/n.height;jt[i].push([r,s]);let a=document.createElement("div");a.className="mark",a.textContent=jt[i].length,a.style.left=e.clientX-n.left+"px",a.style.top=e.clientY-n.top+"px",ve("pick-"+i).appendChild(a),Cc()}function Cc(){let i=Math.min(jt.target.length,jt.source.length);ve("fix-count").textContent=`${jt.target.length} on the target, ${jt.source.length} on the source`,ve("fix-run").disabled=!(i>=3&&jt.target.length===jt.source.length)}async function My(){let{target:i,source:e}=Y.pair.info;ve("fix-run").disabled=!0;try{let t=await Un(`/api/pairs/${encodeURIComponent(i)}/${encodeURIComponent(e)}/register`,{method:"POST",body:JSON.stringify({target_pixels:jt.target,source_pixels:jt.source,reason:ve("fix-reason").value,base_seq:Y.seq,client:Tc})});Jt(`re-aligned: p = ${t.probability.toFixed(3)} (${t.note})`),await Dr(),await Ac(Y.pair.a,Y.pair.b)}catch(t){Jt(t.message,!0),Cc()}}async function wy(){let{items:i}=await Un(`/api/queue?threshold=${Y.tau}`);ve("queue").hidden=!1,ve("queue-list").innerHTML=i.map((e,t)=>`<li data-k="${t}">${e.a} \u2013 ${e.b}: ${e.kind} (${e.why})</li>`).join("")||"<li>nothing uncertain</li>",ve("queue-list").querySelectorAll("li[data-k]").forEach(e=>e.addEventListener("click",()=>{let t=i[+e.dataset.k];ve("queue").hidden=!0,yu(t.a,[t.b],0)}))}function Ey(){Y.renderer.refresh();let i=Y.renderer.getCanvases(),e=Object.values(i)[0],t=document.createElement("canvas");t.width=e.width,t.height=e.height;let n=t.getContext("2d");n.fillStyle="#fff",n.fillRect(0,0,t.width,t.height);for(let r of["edges","nodes","labels","hovers","hoverNodes"])i[r]&&n.drawImage(i[r],0,0);return t.toDataURL("image/png")}function Ty(){let{width:i,height:e}=Y.renderer.getDimensions(),t=[`<svg xmlns="http://www.w3.org/2000/svg" width="${i}" height="${e}" viewBox="0 0 ${i} ${e}">`,'<rect width="100%" height="100%" fill="#fff"/>'],n=r=>Y.renderer.graphToViewport(Y.renderer.getNodeDisplayData(Y.state.nodes[r].id));for(let r=0;r<Y.prob.length;r++){if(!Y.kept[r]||!ar(Y.src[r])||!ar(Y.dst[r]))continue;let s=n(Y.src[r]),a=n(Y.dst[r]);t.push(`<line x1="${s.x.toFixed(1)}" y1="${s.y.toFixed(1)}" x2="${a.x.toFixed(1)}" y2="${a.y.toFixed(1)}" stroke="#9c9588"/>`)}return Y.state.nodes.forEach((r,s)=>{if(!ar(s))return;let a=n(s);t.push(`<circle cx="${a.x.toFixed(1)}" cy="${a.y.toFixed(1)}" r="4" fill="${_u(s)}"><title>${r.id}</title></circle>`)}),t.push("</svg>"),"data:image/svg+xml;charset=utf-8,"+encodeURIComponent(t.join(`
`))}function Ay(){let i=ve("threshold");i.value=Y.tau,ve("threshold-value").textContent=Y.tau.toFixed(2),i.addEventListener("input",()=>{Y.tau=parseFloat(i.value),ve("threshold-value").textContent=Y.tau.toFixed(2),Mc()}),ve("search").addEventListener("change",e=>fu(e.target.value)),ve("search").addEventListener("keydown",e=>{e.key==="Enter"&&fu(e.target.value)});for(let e of["filter-face","filter-size","filter-unverified"])ve(e).addEventListener("input",Mc);ve("undo").onclick=()=>Y.state.undo_target!=null&&Nn("undo",null,null,{target:Y.state.undo_target}),ve("redo").onclick=()=>Y.state.redo_target!=null&&Nn("redo",null,null,{target:Y.state.redo_target}),ve("link-create").onclick=()=>Nn("link",Si(ve("link-a").value),Si(ve("link-b").value)),ve("link-cut").onclick=()=>Nn("cut",Si(ve("link-a").value),Si(ve("link-b").value)),ve("queue-button").onclick=wy,ve("queue-close").onclick=()=>ve("queue").hidden=!0,ve("pair-close").onclick=()=>{ve("pair").hidden=!0,Y.pair=null},ve("pair-accept").onclick=()=>Zs(!0),ve("pair-reject").onclick=()=>Zs(!1),ve("pair-fix").onclick=pu,ve("fix-run").onclick=My,ve("fix-clear").onclick=pu,ve("pick-target").addEventListener("click",e=>mu("target",e)),ve("pick-source").addEventListener("click",e=>mu("source",e)),ve("blend").addEventListener("input",e=>ve("ov-source").style.opacity=e.target.value),ve("flicker").onclick=Sy,document.querySelectorAll("[data-export]").forEach(e=>{e.addEventListener("click",()=>e.href=`/api/export/${e.dataset.export}?threshold=${Y.tau}`),e.href=`/api/export/${e.dataset.export}?threshold=${Y.tau}`}),ve("export-png").addEventListener("click",e=>e.currentTarget.href=Ey()),ve("export-svg").addEventListener("click",e=>e.currentTarget.href=Ty()),document.addEventListener("keydown",e=>{if(!(e.target.tagName==="INPUT"&&e.target.type!=="range")){if((e.ctrlKey||e.metaKey)&&e.key==="z"){ve("undo").click(),e.preventDefault();return}if((e.ctrlKey||e.metaKey)&&e.key==="y"){ve("redo").click(),e.preventDefault();return}ve("pair").hidden||(e.key==="ArrowRight"||e.key==="j"?Ec(1):e.key==="ArrowLeft"||e.key==="k"?Ec(-1):e.key==="a"?Zs(!0):e.key==="r"?Zs(!1):e.key==="Escape"&&ve("pair-close").click())}})}async function Cy(){try{let i=await Un("/api/state");Y.tau=i.threshold,Ay(),await Dr(),Y.ready=!0,wc()}catch(i){console.error(i.stack),document.body.innerHTML=`<p style="padding:2em">coindie: ${i.message}</p>`}}Cy();})();
/*! Bundled license information:

three/build/three.module.js:
  (**
   * @license
   * Copyright 2010-2024 Three.js Authors
   * SPDX-License-Identifier: MIT
   *)
*/
