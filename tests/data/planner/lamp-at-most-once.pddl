(define (problem lamp-once)
  (:domain lamp)
  (:init)
  (:goal (open))
  (:constraints
    (at-most-once (and (lit) (open)))))
